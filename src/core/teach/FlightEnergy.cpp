#include "flight/FlightStateAlgebra.hpp"

#include <abalike/teach/FlightEnergy.hpp>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace abalike
{

namespace
{

/// Nodes and weights of 3-point Gauss-Legendre quadrature on [-1, 1]: exact for polynomials up to degree 5.
const double kGaussNode = std::sqrt(0.6);
constexpr double kGaussCentreWeight = 8.0 / 9.0;
constexpr double kGaussOuterWeight = 5.0 / 9.0;

/// A step of no length at the launch: what the tracker holds before its first step.
FlightStep launchPiece(const FlightState& s0)
{
    FlightStep step;
    step.s0 = step.s1 = s0;
    return step;
}

} // namespace

FlightEnergyTracker::FlightEnergyTracker(const FlightModel& model, const IntegratorSettings& settings,
                                         const FlightState& s0)
    : m_integrator(model, settings), m_s0(s0), m_pieces{launchPiece(s0)}
{
    m_integrator.reset(0.0, s0);
}

void FlightEnergyTracker::advance()
{
    const FlightStep step = m_integrator.step();
    m_pieces.assign(1, step);
    const FlightModel& model = m_integrator.model();
    if (!model.gusts || model.gusts->kind != GustDef::Kind::Steps || (activeTerms(model) & kGustTerm) == 0)
        return;
    std::vector<double> jumps;
    for (const GustDef::Step& gust : model.gusts->steps)
        if (gust.startS > step.t0 && gust.startS < step.t1)
            jumps.push_back(gust.startS);
    if (jumps.empty())
        return;
    // Redo the step's RK4 sub-steps up to each jump as the integrator takes them (stages at the jump itself still
    // see the old gust), and join them with one-sided derivatives there.
    m_pieces.clear();
    double t = step.t0;
    FlightState s = step.s0;
    jumps.push_back(step.t1);
    for (const double stop : jumps)
    {
        FlightStep piece;
        piece.t0 = t;
        piece.s0 = s;
        piece.f0 = m_integrator.rightHandSide(t, s);
        if (stop == step.t1)
            s = step.s1;
        else
        {
            auto system = [&](const FlightState& x, FlightState& dxdt, double tt)
            {
                dxdt = m_integrator.rightHandSide(tt < stop ? tt : std::nextafter(stop, -INFINITY), x);
            };
            FlightRk4().do_step(system, s, piece.f0, t, stop - t);
        }
        piece.t1 = stop;
        piece.s1 = s;
        piece.f1 = stop == step.t1 ? step.f1 : m_integrator.rightHandSide(std::nextafter(stop, -INFINITY), s);
        m_pieces.push_back(piece);
        t = stop;
    }
}

FlightState FlightEnergyTracker::stateAt(double t) const
{
    for (const FlightStep& piece : m_pieces)
        if (t <= piece.t1)
            return piece.interpolate(t);
    return m_pieces.back().s1;
}

double FlightEnergyTracker::dragWork(double t0, double t1) const
{
    const FlightModel& model = m_integrator.model();
    double work = 0.0;
    for (const FlightStep& piece : m_pieces)
    {
        const double a = std::max(t0, piece.t0);
        const double b = std::min(t1, piece.t1);
        if (!(b > a))
            continue;
        const auto powerAt = [&](double t)
        {
            const FlightState s = piece.interpolate(t);
            // Inside the piece, never at the far end where a gust may already have changed.
            const FlightState f = m_integrator.rightHandSide(std::min(t, std::nextafter(piece.t1, -INFINITY)), s);
            // Drag is what is left of the acceleration once gravity is taken out.
            return model.massKg * (f.velocity.x * s.velocity.x + (f.velocity.y + model.gravity) * s.velocity.y);
        };
        const double half = 0.5 * (b - a);
        const double mid = 0.5 * (b + a);
        work += half * (kGaussCentreWeight * powerAt(mid) + kGaussOuterWeight * powerAt(mid - half * kGaussNode) +
                        kGaussOuterWeight * powerAt(mid + half * kGaussNode));
    }
    return -work; // a loss is work done against the bird
}

FlightEnergy FlightEnergyTracker::at(double tS)
{
    if (!(tS >= 0.0) || !std::isfinite(tS))
        throw std::invalid_argument("the time since launch must be a finite number >= 0");
    if (tS < m_pieces.front().t0)
    {
        m_integrator.reset(0.0, m_s0);
        m_pieces.assign(1, launchPiece(m_s0));
        m_lossBeforeStepJ = 0.0;
    }
    while (m_pieces.back().t1 < tS)
    {
        m_lossBeforeStepJ += dragWork(m_pieces.front().t0, m_pieces.back().t1);
        advance();
    }

    const FlightModel& model = m_integrator.model();
    FlightEnergy energy;
    energy.tS = tS;
    energy.state = stateAt(tS);
    energy.dragLossJ = m_lossBeforeStepJ + dragWork(m_pieces.front().t0, tS);
    const auto kinetic = [&](const FlightState& s)
    {
        return 0.5 * model.massKg * (s.velocity.x * s.velocity.x + s.velocity.y * s.velocity.y);
    };
    const auto potential = [&](const FlightState& s)
    {
        return model.massKg * model.gravity * s.position.y;
    };
    energy.kineticJ = kinetic(energy.state);
    energy.potentialJ = potential(energy.state);
    energy.launchKineticJ = kinetic(m_s0);
    energy.launchPotentialJ = potential(m_s0);
    return energy;
}

FlightEnergy flightEnergyAt(const FlightModel& model, const IntegratorSettings& settings, const FlightState& s0,
                            double tS)
{
    return FlightEnergyTracker(model, settings, s0).at(tS);
}

} // namespace abalike
