#pragma once

#include <abalike/flight/FlightModel.hpp>

#include <optional>
#include <vector>

namespace abalike
{

/// What launches at one speed and every angle can reach, sampled where the checks need it.
struct ReachEnvelope
{
    std::vector<std::optional<double>> highestY; ///< per queried x: highest y any path crosses it at; none if none does
    double farthestX = 0.0;                      ///< largest x any path gets to
};

/// Sweeps launches from (x0, y0) at speed over angles -90..90 degrees, each flown for at most maxTimeS or until it
/// has fallen below floorY, and records the highest crossing of every x in xs.
ReachEnvelope reachEnvelope(const FlightModel& model, double x0, double y0, double speedMps,
                            const std::vector<double>& xs, double floorY, double maxTimeS);

} // namespace abalike
