#include "bench/AccuracySweep.hpp"
#include <abalike/util/MedianTimer.hpp>

#include <abalike/flight/ClosedForm.hpp>

#include <algorithm>
#include <benchmark/benchmark.h>
#include <cmath>
#include <limits>

namespace abalike::app
{

namespace
{

/// The reference is sampled on this grid; every swept dt is a whole multiple of it.
constexpr double kReferenceDt = 1.0 / 3840.0;
/// A timed sample should last about this long, so clock resolution does not matter.
constexpr double kSampleS = 2e-3;

/// Positions along a flight at every multiple of kReferenceDt: the closed form or a tight dopri5 run.
class ReferencePath
{
public:
    ReferencePath(const AccuracyProblem& problem, double tolerance) : m_problem(problem)
    {
        m_exact = hasClosedForm(problem.model) && tolerance <= 0.0;
        if (m_exact)
            return;
        IntegratorSettings settings;
        settings.stepper = StepperKind::Dopri5;
        settings.dtS = kReferenceDt;
        settings.tolerance = tolerance;
        FlightIntegrator integrator(problem.model, settings);
        integrator.reset(0.0, problem.s0);
        const auto steps = static_cast<std::size_t>(std::lround(problem.durationS / kReferenceDt));
        m_states.reserve(steps + 1);
        m_states.push_back(problem.s0);
        for (std::size_t i = 0; i < steps; ++i)
            m_states.push_back(integrator.step().s1);
    }

    FlightState at(double t) const
    {
        if (m_exact)
            return *closedFormState(m_problem.model, m_problem.s0, t);
        const auto i = static_cast<std::size_t>(std::lround(t / kReferenceDt));
        return m_states[std::min(i, m_states.size() - 1)];
    }

    /// Largest position distance from another reference over the whole flight.
    double distanceTo(const ReferencePath& other) const
    {
        double worst = 0.0;
        const auto steps = static_cast<std::size_t>(std::lround(m_problem.durationS / kReferenceDt));
        for (std::size_t i = 0; i <= steps; ++i)
        {
            const FlightState a = at(i * kReferenceDt);
            const FlightState b = other.at(i * kReferenceDt);
            worst = std::max(worst, std::hypot(a.position.x - b.position.x, a.position.y - b.position.y));
        }
        return worst;
    }

private:
    const AccuracyProblem& m_problem;
    bool m_exact = false;
    std::vector<FlightState> m_states;
};

SweepPoint measure(const AccuracyProblem& problem, const ReferencePath& reference, StepperKind stepper, double dt,
                   double tolerance, bool quick)
{
    IntegratorSettings settings;
    settings.stepper = stepper;
    settings.dtS = dt;
    if (tolerance > 0.0)
        settings.tolerance = tolerance;
    const auto steps = static_cast<std::size_t>(std::lround(problem.durationS / dt));

    SweepPoint point;
    point.stepper = stepper;
    point.dtS = dt;
    point.tolerance = tolerance;
    point.steps = steps;
    {
        FlightIntegrator integrator(problem.model, settings);
        integrator.reset(0.0, problem.s0);
        for (std::size_t i = 0; i < steps; ++i)
        {
            const FlightStep& step = integrator.step();
            // The output time is i dt, not the integrator's summed time: the reference grid is exact multiples.
            const FlightState exact = reference.at(static_cast<double>(i + 1) * dt);
            const double error =
                std::hypot(step.s1.position.x - exact.position.x, step.s1.position.y - exact.position.y);
            point.maxError = std::max(point.maxError, error);
            point.finalError = error;
        }
        point.rhsEvaluations = integrator.rhsEvaluations();
    }

    auto integrate = [&]
    {
        FlightIntegrator integrator(problem.model, settings);
        integrator.reset(0.0, problem.s0);
        for (std::size_t i = 0; i < steps; ++i)
            integrator.step();
        benchmark::DoNotOptimize(integrator.state());
    };
    const double once = medianSeconds(integrate, 3);
    const int batch = std::max(1, static_cast<int>(kSampleS / std::max(once, 1e-9)));
    point.seconds = medianSeconds(integrate, quick ? 5 : 21, batch);
    return point;
}

} // namespace

std::vector<AccuracyProblem> accuracyProblems()
{
    std::vector<AccuracyProblem> problems;
    const FlightState launch = launchState(0.0, 1.5, 30.0, 50.0);

    AccuracyProblem vacuum{"vacuum", "vacuum (exact: parabola)", FlightModel{}, launch, 4.0};
    problems.push_back(vacuum);

    AccuracyProblem linear{"linear-drag", "linear drag b/m = 0.5 1/s (exact)", FlightModel{}, launch, 4.0};
    linear.model.linearDrag = 0.5;
    problems.push_back(linear);

    // The red bird (4 kg, r = 0.25 m, Cd 0.47) in sea-level air: c = 0.055 kg/m.
    AccuracyProblem quadratic{"quadratic-drag", "quadratic drag, red bird in air (dopri5 reference)", FlightModel{},
                              launch, 4.0};
    quadratic.model.massKg = 4.0;
    quadratic.model.quadraticDrag = quadraticDragCoefficient(1.2, 0.47, 0.25);
    problems.push_back(quadratic);

    AccuracyProblem windy = quadratic;
    windy.name = "wind-quadratic-drag";
    windy.label = "quadratic drag + wind (-6, 1.5) m/s (dopri5 reference)";
    windy.model.windX = -6.0;
    windy.model.windY = 1.5;
    problems.push_back(windy);
    return problems;
}

ProblemSweep sweepProblem(const AccuracyProblem& problem, bool quick)
{
    ProblemSweep sweep;
    sweep.problem = problem;
    sweep.exactReference = hasClosedForm(problem.model);
    const ReferencePath reference(problem, sweep.exactReference ? 0.0 : 1e-13);
    {
        // How good the reference is: dopri5 at 1e-13 against 1e-12 (or against the closed form).
        const ReferencePath tight(problem, 1e-13);
        const ReferencePath looser(problem, 1e-12);
        if (sweep.exactReference)
            sweep.dopriVsExact = tight.distanceTo(reference);
        else
            sweep.referenceError = tight.distanceTo(looser);
    }

    const std::vector<int> eulerRates =
        quick ? std::vector<int>{30, 60, 120, 240, 480} : std::vector<int>{15, 30, 60, 120, 240, 480, 960, 1920, 3840};
    const std::vector<int> rk4Rates =
        quick ? std::vector<int>{10, 20, 40, 60, 120} : std::vector<int>{5, 10, 15, 20, 30, 40, 60, 120, 240};
    for (const StepperKind stepper : {StepperKind::Euler, StepperKind::SemiImplicitEuler})
        for (const int rate : eulerRates)
            sweep.points.push_back(measure(problem, reference, stepper, 1.0 / rate, 0.0, quick));
    for (const int rate : rk4Rates)
        sweep.points.push_back(measure(problem, reference, StepperKind::Rk4, 1.0 / rate, 0.0, quick));
    const std::vector<double> tolerances =
        quick ? std::vector<double>{1e-3, 1e-5, 1e-7, 1e-9, 1e-11}
              : std::vector<double>{1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11};
    for (const double tol : tolerances)
        sweep.points.push_back(measure(problem, reference, StepperKind::Dopri5, 1.0 / 60.0, tol, quick));
    if (sweep.exactReference)
        for (const int rate : {5, 15, 60, 240, 960})
            sweep.points.push_back(measure(problem, reference, StepperKind::Analytic, 1.0 / rate, 0.0, quick));
    return sweep;
}

double convergenceOrder(const ProblemSweep& sweep, StepperKind stepper)
{
    // Points within 1000x of the reference's error (or of rounding, ~1e-12 m here) say nothing about the order.
    const double floor = 1e3 * std::max(sweep.referenceError, 1e-12);
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    int n = 0;
    for (const SweepPoint& p : sweep.points)
    {
        if (p.stepper != stepper || !(p.finalError > floor))
            continue;
        const double x = std::log(p.dtS);
        const double y = std::log(p.finalError);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
        ++n;
    }
    if (n < 3)
        return std::numeric_limits<double>::quiet_NaN();
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

} // namespace abalike::app
