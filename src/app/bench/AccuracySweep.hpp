#pragma once

#include <abalike/flight/FlightIntegrator.hpp>

#include <string>
#include <vector>

namespace abalike::app
{

/// A flight whose integration error is measured: a model, a launch and a duration.
struct AccuracyProblem
{
    std::string name;  ///< short id for files and CSV
    std::string label; ///< what it is, for tables and plots
    FlightModel model;
    FlightState s0{};
    double durationS = 4.0;
};

/// Vacuum and linear drag (closed forms), quadratic drag and quadratic drag with wind (reference by dopri5).
std::vector<AccuracyProblem> accuracyProblems();

/// One integration of a problem with one method and one step or tolerance.
struct SweepPoint
{
    StepperKind stepper = StepperKind::Rk4;
    double dtS = 0.0;
    double tolerance = 0.0; ///< dopri5 only
    std::size_t steps = 0;
    std::size_t rhsEvaluations = 0;
    double seconds = 0.0;    ///< median wall time of one whole integration
    double finalError = 0.0; ///< position error at the end (m)
    double maxError = 0.0;   ///< largest position error at any output step (m)
};

/// All methods of one problem, and how good its reference is.
struct ProblemSweep
{
    AccuracyProblem problem;
    std::vector<SweepPoint> points;
    bool exactReference = false;
    double referenceError = 0.0; ///< closed form: 0; dopri5 at 1e-13: its distance from a run at 1e-12 (m)
    double dopriVsExact = 0.0;   ///< closed-form problems: the 1e-13 dopri5 run's own error, as a check (m)
};

/// Integrates the problem with every method over a sweep of dt (or tolerance) and times each.
ProblemSweep sweepProblem(const AccuracyProblem& problem, bool quick);

/// Least-squares slope of log(error) against log(dt) for one fixed-step method, over the points whose error is
/// well above the reference's own error; NaN if fewer than three such points.
double convergenceOrder(const ProblemSweep& sweep, StepperKind stepper);

} // namespace abalike::app
