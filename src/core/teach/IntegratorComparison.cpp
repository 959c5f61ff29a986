#include <abalike/teach/IntegratorComparison.hpp>
#include <abalike/util/MedianTimer.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace abalike
{

IntegratorSettings ComparisonMethod::settings(double physicsDtS) const
{
    IntegratorSettings s;
    s.stepper = stepper;
    s.guardStiffness = false;
    s.dtS = stepper == StepperKind::Dopri5 ? physicsDtS : dtS;
    if (stepper == StepperKind::Dopri5)
        s.tolerance = tolerance; // the fixed-step methods never use it
    return s;
}

std::string ComparisonMethod::label() const
{
    char text[96];
    if (stepper == StepperKind::Dopri5)
    {
        std::snprintf(text, sizeof text, "dopri5, tol = %.0e", tolerance);
        return text;
    }
    const char* name = stepper == StepperKind::Euler               ? "explicit Euler"
                       : stepper == StepperKind::SemiImplicitEuler ? "semi-implicit Euler"
                       : stepper == StepperKind::Rk4               ? "RK4"
                                                                   : "analytic";
    const double rate = 1.0 / dtS;
    if (std::abs(rate - std::round(rate)) < 1e-9 * rate)
        std::snprintf(text, sizeof text, "%s, dt = 1/%.0f s", name, rate);
    else
        std::snprintf(text, sizeof text, "%s, dt = %.4g s", name, dtS);
    return text;
}

namespace
{

/// Median microseconds of integrating `durationS` seconds with these settings, with no contact tests: the cost of
/// the method alone.
double integrationMicros(const FlightModel& model, const IntegratorSettings& settings, const FlightState& s0,
                         double durationS)
{
    const auto steps = static_cast<std::size_t>(std::ceil(durationS / settings.dtS));
    volatile double sink = 0.0; // keeps the work from being optimised away
    const auto run = [&]
    {
        FlightIntegrator integrator(model, settings);
        integrator.reset(0.0, s0);
        for (std::size_t i = 0; i < steps; ++i)
            integrator.step();
        sink = sink + integrator.state().position.x;
    };
    return 1e6 * medianSeconds(run, 7, 4);
}

} // namespace

FlightState pathStateAt(const FlightIntegrator& rhs, const PredictedFlight& flight, double tS)
{
    const std::vector<PathPoint>& path = flight.path;
    if (path.empty())
        return {};
    if (tS <= path.front().timeS)
        return path.front().state;
    if (tS >= path.back().timeS)
        return path.back().state;
    const auto after =
        std::upper_bound(path.begin(), path.end(), tS, [](double t, const PathPoint& p) { return t < p.timeS; });
    const PathPoint& a = *(after - 1);
    const PathPoint& b = *after;
    FlightStep step;
    step.t0 = a.timeS;
    step.t1 = b.timeS;
    step.s0 = a.state;
    step.s1 = b.state;
    step.f0 = rhs.rightHandSide(a.timeS, a.state);
    step.f1 = rhs.rightHandSide(b.timeS, b.state);
    return step.interpolate(tS);
}

IntegratorComparison compareIntegrator(const FlightModel& model, const FlightState& s0, const ComparisonMethod& method,
                                       double physicsDtS, const PredictedFlight& real, const PredictionLimits& limits,
                                       ComparisonCost cost)
{
    if (method.stepper == StepperKind::Dopri5)
    {
        if (!(method.tolerance >= kComparisonMinTolerance && method.tolerance <= kComparisonMaxTolerance))
            throw std::invalid_argument("the compared dopri5's tolerance must be between 1e-12 and 1e-2");
    }
    else if (method.stepper == StepperKind::Analytic)
        throw std::invalid_argument("compare euler, semi-implicit-euler, rk4 or dopri5");
    else if (!(method.dtS >= kComparisonMinDtS * (1.0 - 1e-12) && method.dtS <= kComparisonMaxDtS * (1.0 + 1e-12)))
        throw std::invalid_argument("the compared method's step must be between 1/240 and 1/15 s");

    IntegratorComparison comparison;
    comparison.method = method;
    comparison.flight = predictFlight(model, method.settings(physicsDtS), s0, limits);
    if (real.path.empty())
        return comparison;
    const FlightIntegrator rhs(model, {});
    const double end = std::min(comparison.flight.path.back().timeS, real.path.back().timeS);
    for (const PathPoint& p : comparison.flight.path)
    {
        if (p.timeS > end)
            break;
        const FlightState r = pathStateAt(rhs, real, p.timeS);
        comparison.maxErrorM = std::max(
            comparison.maxErrorM, std::hypot(p.state.position.x - r.position.x, p.state.position.y - r.position.y));
    }
    if (comparison.flight.contact && real.contact)
        comparison.contactErrorM =
            std::hypot(comparison.flight.contact->x - real.contact->x, comparison.flight.contact->y - real.contact->y);
    if (cost == ComparisonCost::Measure)
    {
        const double duration = std::max(real.path.back().timeS, physicsDtS);
        comparison.costUs = integrationMicros(model, method.settings(physicsDtS), s0, duration);
        IntegratorSettings rk4;
        rk4.dtS = physicsDtS;
        comparison.realCostUs = integrationMicros(model, rk4, s0, duration);
    }
    return comparison;
}

} // namespace abalike
