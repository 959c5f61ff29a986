#pragma once

#include <abalike/flight/FlightModel.hpp>

#include <string>
#include <vector>

namespace abalike::app
{

/// One extreme flight: a model and a launch flown for a long time.
struct StabilityCase
{
    std::string group; ///< what is being pushed: stiff drag, speed, angle, gravity, mass, launch point
    std::string name;
    FlightModel model;
    FlightState s0{};
    double durationS = 60.0;
};

/// What plain RK4 and the guarded preview made of a case, against a tight dopri5 reference.
struct StabilityResult
{
    double launchLambdaDt = 0.0; ///< |lambda| dt at launch, dt = 1/60 s
    bool plainFinite = true;
    double plainBlowUpS = 0.0; ///< when plain RK4 first went non-finite
    double plainError = 0.0;   ///< largest position error along the path / largest distance flown
    std::string guard;         ///< what the guard did: none, substep, rosenbrock4
    std::size_t substeps = 0;
    double guardedError = 0.0;
    double guardedUs = 0.0;         ///< median wall time of the guarded 60 s integration
    std::size_t referenceSteps = 0; ///< output steps of the reference run (same grid)
    bool passed = false;            ///< guarded run finite and within kStabilityTolerance of the reference
};

/// The guarded preview must stay within this relative error of the reference (the 1e-3).
inline constexpr double kStabilityTolerance = 1e-3;

/// Stiff drag across |lambda| dt = 2.78, speeds 0..1000 m/s, angles -90..90, gravity 0 / 0.01 / 100, masses 1e-4 ..
/// 1e4 kg, launch points 10 km out, gusts; 60 s flights.
std::vector<StabilityCase> stabilityCases(bool quick);

/// Flies a case with plain RK4, the guarded RK4 preview and dopri5 at 1e-12 (the reference), all at 1/60 s output.
StabilityResult runStabilityCase(const StabilityCase& c, bool quick);

} // namespace abalike::app
