#pragma once

#include <abalike/flight/FlightIntegrator.hpp>
#include <functional>
#include <optional>
#include <vector>

namespace abalike
{

/// A point of a flight path in time.
struct PathPoint
{
    PathPoint() = default;
    /// So that a path's vector builds each point in place (emplace_back; clang 14 has no parenthesised aggregate
    /// initialisation).
    PathPoint(double time, const FlightState& at) : timeS(time), state(at) {}

    double timeS = 0.0;
    FlightState state{};
};

/// Where and when a flight first meets something.
struct ContactPoint
{
    double t = 0.0;
    double x = 0.0;
    double y = 0.0;
};

/// Answers "does the bird touch level geometry while moving in a straight line from a to b?" with the
/// fraction along the segment (0..1) of the first touch, or nullopt. The world implements it with the same
/// time-of-impact query Box2D uses for bullets, so prediction and world agree on where contact happens.
using ContactQuery = std::function<std::optional<double>(const FlightState& a, const FlightState& b)>;

/// Why a predicted flight stopped.
enum class FlightEnd
{
    Contact,  ///< touched geometry (ContactQuery)
    Landed,   ///< came back down to the launch height (or PredictionLimits::landingY)
    TimeUp,   ///< reached the requested end time
    Diverged, ///< the state left the range of double (e.g. drag so strong it overflows); the path stops before it
};

/// A predicted flight: the integrator's steps from launch to where it ended.
struct PredictedFlight
{
    std::vector<PathPoint> path; ///< one point per step; the last is the end point (contact or landing)
    FlightEnd end = FlightEnd::TimeUp;
    std::optional<ContactPoint> contact;
    std::size_t steps = 0;
    std::size_t rhsEvaluations = 0;
    std::size_t substeps = 0;
    double maxStiffnessRatio = 0.0;
    GuardAction guard = GuardAction::None; ///< what the stiffness guard did
    double maxHeightM = 0.0;
};

/// What ends a prediction.
struct PredictionLimits
{
    double maxTimeS = 60.0;           ///< hard stop
    bool stopOnLanding = false;       ///< stop where y comes back down to the launch height
    std::optional<double> landingY;   ///< with stopOnLanding: stop where y comes down to this height instead
    std::optional<double> untilTimeS; ///< stop exactly here (overrides landing)
    ContactQuery contact;             ///< stop at the first contact, if set
};

/// Integrates a flight from s0 (at t = 0) until it ends by the given limits. Landing and the until-time are
/// located inside the last step by Hermite interpolation, not snapped to the step's end.
PredictedFlight predictFlight(const FlightModel& model, const IntegratorSettings& settings, const FlightState& s0,
                              const PredictionLimits& limits);

} // namespace abalike
