#include <abalike/flight/FlightIntegrator.hpp>
#include <abalike/flight/FlightRhs.hpp>

#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace abalike
{

namespace odeint = boost::numeric::odeint;

/// Shared state of an integration; the derived class holds the composed right-hand side and the steppers.
class FlightIntegrator::Impl
{
public:
    Impl(const FlightModel& model, const IntegratorSettings& settings) : model(model), settings(settings) {}
    virtual ~Impl() = default;

    virtual void reset(double t, const FlightState& s) = 0;
    virtual void advance() = 0;
    virtual FlightState rhsAt(double t, const FlightState& s) const = 0;

    FlightModel model; // owns the gusts the right-hand side points at
    IntegratorSettings settings;
    FlightStep last;
    double time = 0.0;
    FlightState state{};
    FlightState derivative{};
    std::size_t evaluations = 0;
    std::size_t substeps = 0;
    double maxStiffnessRatio = 0.0;
};

namespace
{

/// |lambda| h above which a fixed-step method is sub-stepped. Well inside the stability limits on the negative
/// real axis (Euler 2, RK4 2.785) so a guarded step is also accurate, not just stable.
double stiffnessLimit(StepperKind kind)
{
    return kind == StepperKind::Rk4 ? 1.0 : 0.5;
}

template <class Rhs>
class TypedImpl final : public FlightIntegrator::Impl
{
public:
    using Dopri = odeint::runge_kutta_dopri5<FlightState>;
    using DenseDopri = odeint::dense_output_runge_kutta<odeint::controlled_runge_kutta<Dopri>>;

    TypedImpl(const FlightModel& m, const IntegratorSettings& s) : Impl(m, s), m_rhs(model)
    {
        if (settings.stepper == StepperKind::Analytic &&
            (Rhs::kTerms & (kQuadraticDragTerm | kGustTerm)) != 0)
            throw std::invalid_argument(
                "the analytic stepper has no closed form with quadratic drag or gusts; use rk4 or dopri5");
    }

    void reset(double t, const FlightState& s) override
    {
        time = t;
        state = s;
        evaluate(state, derivative, time);
        if (settings.stepper == StepperKind::Dopri5)
        {
            m_dense.emplace(odeint::make_dense_output(settings.tolerance, settings.tolerance, Dopri()));
            m_dense->initialize(state, time, settings.dtS);
        }
    }

    void advance() override
    {
        last.t0 = time;
        last.s0 = state;
        last.f0 = derivative;
        const double h = settings.dtS;
        switch (settings.stepper)
        {
        case StepperKind::Dopri5:
            advanceDense(time + h);
            break;
        case StepperKind::Analytic:
            advanceAnalytic(h);
            break;
        default:
            advanceFixed(h);
            break;
        }
        time = last.t0 + h;
        evaluate(state, derivative, time);
        last.t1 = time;
        last.s1 = state;
        last.f1 = derivative;
    }

    FlightState rhsAt(double t, const FlightState& s) const override
    {
        FlightState dsdt{};
        m_rhs(s, dsdt, t);
        return dsdt;
    }

private:
    void evaluate(const FlightState& s, FlightState& dsdt, double t)
    {
        ++evaluations;
        m_rhs(s, dsdt, t);
    }

    void advanceFixed(double h)
    {
        int pieces = 1;
        const double ratio = m_rhs.stiffness(state, time) * h;
        if (settings.guardStiffness && ratio > stiffnessLimit(settings.stepper))
            pieces = static_cast<int>(std::ceil(ratio / stiffnessLimit(settings.stepper)));
        substeps += static_cast<std::size_t>(pieces - 1);
        maxStiffnessRatio = std::max(maxStiffnessRatio, ratio / pieces);

        const double hs = h / pieces;
        double t = time;
        FlightState f = derivative;
        auto system = [this](const FlightState& x, FlightState& dxdt, double tt) { evaluate(x, dxdt, tt); };
        for (int i = 0; i < pieces; ++i)
        {
            if (i > 0)
                evaluate(state, f, t);
            switch (settings.stepper)
            {
            case StepperKind::Euler:
                m_euler.do_step(system, state, f, t, hs);
                break;
            case StepperKind::SemiImplicitEuler:
                // Box2D's scheme: velocity first, then position with the new velocity.
                state[2] += hs * f[2];
                state[3] += hs * f[3];
                state[0] += hs * state[2];
                state[1] += hs * state[3];
                break;
            default:
                m_rk4.do_step(system, state, f, t, hs);
                break;
            }
            t = time + (i + 1) * hs;
        }
    }

    void advanceDense(double target)
    {
        auto system = [this](const FlightState& x, FlightState& dxdt, double tt) { evaluate(x, dxdt, tt); };
        std::size_t internal = 0;
        while (m_dense->current_time() < target)
        {
            m_dense->do_step(system);
            ++internal;
        }
        if (internal > 1)
            substeps += internal - 1;
        m_dense->calc_state(target, state);
    }

    void advanceAnalytic(double h)
    {
        const double g = model.gravity;
        const double k = model.linearDrag / model.massKg;
        if ((Rhs::kTerms & kLinearDragTerm) == 0)
        {
            state[0] += state[2] * h;
            state[1] += state[3] * h - 0.5 * g * h * h;
            state[3] -= g * h;
            return;
        }
        // Linear drag relaxes v towards the terminal velocity u = w + g/k; expm1 keeps 1 - exp(-kh) exact for small kh.
        const double wx = (Rhs::kTerms & kWindTerm) != 0 ? model.windX : 0.0;
        const double wy = (Rhs::kTerms & kWindTerm) != 0 ? model.windY : 0.0;
        const double ux = wx;
        const double uy = wy - g / k;
        const double oneMinusE = -std::expm1(-k * h);
        const double e = 1.0 - oneMinusE;
        state[0] += ux * h + (state[2] - ux) * oneMinusE / k;
        state[1] += uy * h + (state[3] - uy) * oneMinusE / k;
        state[2] = ux + (state[2] - ux) * e;
        state[3] = uy + (state[3] - uy) * e;
    }

    Rhs m_rhs;
    odeint::runge_kutta4<FlightState> m_rk4;
    odeint::euler<FlightState> m_euler;
    std::optional<DenseDopri> m_dense;
};

} // namespace

FlightIntegrator::FlightIntegrator(const FlightModel& model, const IntegratorSettings& settings)
{
    if (!(settings.dtS > 0.0) || !std::isfinite(settings.dtS))
        throw std::invalid_argument("the time step must be a finite number > 0");
    if (!(settings.tolerance > 0.0) || !std::isfinite(settings.tolerance))
        throw std::invalid_argument("the tolerance must be a finite number > 0");
    if (const std::string problem = validateFlightModel(model); !problem.empty())
        throw std::invalid_argument(problem);
    m_impl = visitFlightRhs(model, [&](auto rhs) -> std::unique_ptr<Impl> {
        return std::make_unique<TypedImpl<decltype(rhs)>>(model, settings);
    });
    m_impl->reset(0.0, FlightState{});
    m_impl->evaluations = 0;
}

FlightIntegrator::~FlightIntegrator() = default;
FlightIntegrator::FlightIntegrator(FlightIntegrator&&) noexcept = default;
FlightIntegrator& FlightIntegrator::operator=(FlightIntegrator&&) noexcept = default;

void FlightIntegrator::reset(double t, const FlightState& s)
{
    m_impl->reset(t, s);
}

const FlightStep& FlightIntegrator::step()
{
    m_impl->advance();
    return m_impl->last;
}

double FlightIntegrator::time() const
{
    return m_impl->time;
}

const FlightState& FlightIntegrator::state() const
{
    return m_impl->state;
}

const FlightModel& FlightIntegrator::model() const
{
    return m_impl->model;
}

const IntegratorSettings& FlightIntegrator::settings() const
{
    return m_impl->settings;
}

std::size_t FlightIntegrator::rhsEvaluations() const
{
    return m_impl->evaluations;
}

std::size_t FlightIntegrator::substeps() const
{
    return m_impl->substeps;
}

double FlightIntegrator::maxStiffnessRatio() const
{
    return m_impl->maxStiffnessRatio;
}

FlightState FlightIntegrator::rightHandSide(double t, const FlightState& s) const
{
    return m_impl->rhsAt(t, s);
}

const FlightState& FlightIntegrator::derivative() const
{
    return m_impl->derivative;
}

} // namespace abalike
