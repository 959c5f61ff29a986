#include "flight/FlightStateAlgebra.hpp"
#include "flight/Rosenbrock4.hpp"

#include <abalike/flight/ClosedForm.hpp>
#include <abalike/flight/FlightIntegrator.hpp>
#include <abalike/flight/FlightRhs.hpp>
#include <algorithm>
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
    std::size_t guardedSteps = 0;
    std::size_t implicitSteps = 0;
    double maxStiffnessRatio = 0.0;
};

namespace
{

template <class Rhs>
class TypedImpl final : public FlightIntegrator::Impl
{
public:
    using Dopri = FlightDopri5;
    using DenseDopri = odeint::dense_output_runge_kutta<odeint::controlled_runge_kutta<Dopri>>;

    TypedImpl(const FlightModel& m, const IntegratorSettings& s) : Impl(m, s), m_rhs(model)
    {
        if (settings.stepper == StepperKind::Analytic && !hasClosedForm(model))
            throw std::invalid_argument(
                "the analytic stepper has no closed form with quadratic drag or gusts; use rk4 or dopri5");
    }

    void reset(double t, const FlightState& s) override
    {
        time = t;
        state = s;
        evaluate(state, derivative, time);
        m_implicit.reset();
        m_lastStepImplicit = false;
        if (settings.stepper == StepperKind::Dopri5)
        {
            m_dense.emplace(odeint::make_dense_output(settings.tolerance, settings.tolerance, Dopri()));
            m_denseStepsTotal = 0;
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
        const double end = time + h;
        const double limit = settings.guardLimit > 0.0 ? settings.guardLimit : defaultGuardLimit(settings.stepper);
        // Stages of a sub-step are evaluated before its stop time: a stepwise gust that starts exactly there belongs
        // to the next sub-step (the last RK4 stage sits at the stop time itself).
        double stageEnd = end;
        auto system = [this, &stageEnd](const FlightState& x, FlightState& dxdt, double tt)
        {
            if constexpr ((Rhs::kTerms & kGustTerm) != 0)
                tt = tt < stageEnd ? tt : std::nextafter(stageEnd, -INFINITY);
            else
                (void)stageEnd;
            evaluate(x, dxdt, tt);
        };
        double t = time;
        FlightState f = derivative;
        const double maxExplicit =
            settings.maxExplicitSubsteps > 0 ? settings.maxExplicitSubsteps : kDefaultMaxExplicitSubsteps;
        std::size_t pieces = 0;
        bool guarded = false;
        bool implicit = false;
        while (t < end)
        {
            if (pieces > 0)
                evaluate(state, f, t);
            double stop = end;
            // A gust that changes in steps makes the right-hand side jump: end a sub-step exactly there so the
            // method keeps its order instead of integrating across the jump.
            if (const auto jump = nextGustJump(t, end))
                stop = *jump;
            double hs = stop - t;
            // The drag's |lambda| is re-estimated at every sub-step: a fast, light bird slows down within a few
            // sub-steps, so the sub-steps grow geometrically instead of staying at the launch's smallest size.
            const double lambda = m_rhs.stiffness(state, t);
            if (settings.guardStiffness && lambda * hs > limit * (1.0 + 1e-12))
            {
                const double needed = std::ceil(lambda * hs / limit);
                // A fast bird's stiffness decays within a few explicit sub-steps. Stiffness that persists (strong
                // drag on a very light bird) would need as many on every step: once a step has used up its explicit
                // budget, or the last step already had to, the linearly implicit rosenbrock4 takes the rest.
                if (static_cast<double>(pieces) >= maxExplicit || (m_lastStepImplicit && needed > maxExplicit))
                {
                    pieces += advanceImplicit(t, stop);
                    implicit = true;
                    t = stop;
                    continue;
                }
                hs /= needed;
                guarded = true;
            }
            // Land exactly on the stop time rather than leave a sliver of a step to rounding.
            const double next = stop - (t + hs) <= 1e-9 * h ? stop : t + hs;
            hs = next - t;
            stageEnd = next;
            maxStiffnessRatio = std::max(maxStiffnessRatio, lambda * hs);
            switch (settings.stepper)
            {
            case StepperKind::Euler:
                m_euler.do_step(system, state, f, t, hs);
                break;
            case StepperKind::SemiImplicitEuler:
                // Box2D's scheme: velocity first, then position with the new velocity.
                state.velocity.x += hs * f.velocity.x;
                state.velocity.y += hs * f.velocity.y;
                state.position.x += hs * state.velocity.x;
                state.position.y += hs * state.velocity.y;
                break;
            default:
                m_rk4.do_step(system, state, f, t, hs);
                break;
            }
            t = next;
            ++pieces;
        }
        substeps += pieces - 1;
        if (guarded)
            ++guardedSteps;
        if (implicit)
            ++implicitSteps;
        m_lastStepImplicit = implicit;
    }

    /// Integrates state from t0 to t1 with rosenbrock4 at the settings' tolerance; returns its step count.
    std::size_t advanceImplicit(double t0, double t1)
    {
        auto system = [this, t1](const FlightState& x, FlightState& dxdt, double t)
        {
            // As in advanceFixed: a gust step starting at t1 belongs to the next step.
            if constexpr ((Rhs::kTerms & kGustTerm) != 0)
                t = t < t1 ? t : std::nextafter(t1, -INFINITY);
            else
                (void)t1;
            evaluate(x, dxdt, t);
        };
        auto jacobian = [this](const FlightState& x, double t, std::array<double, 4>& dadv, Vec2& dadt)
        {
            m_rhs.accelerationJacobian(x, t, dadv, dadt);
        };
        return std::max<std::size_t>(m_implicit.integrate(system, jacobian, state, t0, t1, settings.tolerance), 1);
    }

    /// First time in (t0, t1) where a stepwise gust changes, if the model has one.
    std::optional<double> nextGustJump(double t0, double t1) const
    {
        if constexpr ((Rhs::kTerms & kGustTerm) != 0)
        {
            if (model.gusts->kind == GustDef::Kind::Steps)
                for (const GustDef::Step& step : model.gusts->steps)
                    if (step.startS > t0 && step.startS < t1)
                        return step.startS;
        }
        else
        {
            (void)t0;
            (void)t1;
        }
        return std::nullopt;
    }

    static constexpr std::size_t kMaxDenseSteps = 1000000;
    std::size_t m_denseStepsTotal = 0;

    void advanceDense(double target)
    {
        // The dense stepper caches the derivative at its current point (FSAL) between calls: it is only ever given
        // this same system and its own state, and reset() builds a new one for a new flight.
        auto system = [this](const FlightState& x, FlightState& dxdt, double tt)
        {
            evaluate(x, dxdt, tt);
        };
        std::size_t internal = 0;
        while (m_dense->current_time() < target)
        {
            m_dense->do_step(system);
            ++internal;
            // An explicit adaptive method on a stiff flight shrinks its steps without end; stop with a clear answer
            // instead of hanging. The guarded rk4 handles stiffness.
            if (++m_denseStepsTotal > kMaxDenseSteps)
                throw std::invalid_argument("dopri5 needed more than a million steps: the flight is too stiff for an "
                                            "explicit adaptive method at this tolerance (use --stepper rk4, which "
                                            "guards against stiffness)");
        }
        if (internal > 1)
            substeps += internal - 1;
        m_dense->calc_state(target, state);
    }

    void advanceAnalytic(double h)
    {
        // Exact over any step; stepping through the output steps only adds rounding.
        state = *closedFormState(model, state, h);
    }

    Rhs m_rhs;
    FlightRk4 m_rk4;
    FlightEuler m_euler;
    std::optional<DenseDopri> m_dense;
    detail::Rosenbrock4 m_implicit;
    bool m_lastStepImplicit = false; ///< the previous output step ended in rosenbrock4: stiffness persists
};

} // namespace

FlightIntegrator::FlightIntegrator(const FlightModel& model, const IntegratorSettings& settings)
{
    if (!(settings.dtS > 0.0) || !std::isfinite(settings.dtS))
        throw std::invalid_argument("the time step must be a finite number > 0");
    if (!(settings.tolerance >= 1e-14) || !std::isfinite(settings.tolerance))
        throw std::invalid_argument("the tolerance must be a finite number >= 1e-14 (finer is below what a double "
                                    "can resolve, and the adaptive step would shrink without end)");
    if (const std::string problem = validateFlightModel(model); !problem.empty())
        throw std::invalid_argument(problem);
    m_impl = visitFlightRhs(model,
                            [&](auto rhs) -> std::unique_ptr<Impl>
                            { return std::make_unique<TypedImpl<decltype(rhs)>>(model, settings); });
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

GuardAction FlightIntegrator::guardAction() const
{
    if (!m_impl->settings.guardStiffness)
        return GuardAction::Off;
    if (m_impl->implicitSteps > 0)
        return GuardAction::Implicit;
    return m_impl->guardedSteps > 0 ? GuardAction::Substep : GuardAction::None;
}

double defaultGuardLimit(StepperKind kind)
{
    // Measured on stiff quadratic and linear drag (docs/flight-numerics.md): at 0.5 guarded RK4 stays below
    // 1e-4 relative to a tight dopri5 run, at 1.0 it reaches 1.8e-3. The Euler methods (stable below 2) are
    // first order anyway; 0.5 also keeps them from oscillating (monotone below 1).
    switch (kind)
    {
    case StepperKind::Euler:
    case StepperKind::SemiImplicitEuler:
    case StepperKind::Rk4:
        return 0.5;
    default:
        return 0.0; // dopri5 controls its own step; the analytic stepper is exact
    }
}

std::string_view guardActionName(GuardAction action)
{
    switch (action)
    {
    case GuardAction::Off:
        return "off";
    case GuardAction::None:
        return "none";
    case GuardAction::Substep:
        return "substep";
    case GuardAction::Implicit:
        return "rosenbrock4";
    }
    return "unknown";
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
