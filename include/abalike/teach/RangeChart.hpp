#pragma once

#include <abalike/flight/FlightIntegrator.hpp>
#include <optional>
#include <vector>

namespace abalike
{

/// A launch whose range is charted against its angle: the flight model, the speed and the height above flat ground.
struct RangeLaunch
{
    FlightModel model;
    IntegratorSettings settings; ///< RK4 at the physics step by default, with the stiffness guard
    double speedMps = 0.0;
    double heightM = 0.0;   ///< launch height above the ground (>= 0); the ground is y = 0
    double maxTimeS = 60.0; ///< a flight still in the air after this has no range
};

/// Signed horizontal distance from the launch to where the flight comes down to the ground (y = 0), the landing
/// located inside its step as predictFlight does. 0 for a launch from the ground that does not point upwards;
/// nullopt when it does not land within maxTimeS (or the forces overflow a double).
std::optional<double> rangeAtAngle(const RangeLaunch& launch, double angleDeg);

/// Range against launch angle on a grid, and the best angle refined between grid points.
struct RangeChart
{
    std::vector<double> anglesDeg;
    std::vector<std::optional<double>> rangesM; ///< one per angle; nullopt: did not land in time
    std::optional<double> bestAngleDeg;         ///< nullopt when no angle lands
    std::optional<double> bestRangeM;
};

/// Angles from fromDeg to toDeg (inclusive where the step reaches it) in steps of stepDeg; the best angle is
/// refined by golden-section search on the neighbouring grid interval to better than 0.01 degrees. Throws
/// std::invalid_argument for an empty or too fine grid (more than kMaxRangeChartAngles), angles outside -90..90, a
/// negative height or speed, or an invalid model.
RangeChart rangeChart(const RangeLaunch& launch, double fromDeg, double toDeg, double stepDeg);

/// Most angles one chart may have.
inline constexpr std::size_t kMaxRangeChartAngles = 100000;

} // namespace abalike
