#pragma once

#include <abalike/util/Vec2.hpp>
#include <cmath>

namespace abalike
{

/// Free-flight state of a bird; y points up. odeint integrates it through FlightStateAlgebra (src/core/flight),
/// number by number in this order: position.x, position.y, velocity.x, velocity.y.
struct FlightState
{
    Vec2 position; ///< m
    Vec2 velocity; ///< m/s

    bool operator==(const FlightState&) const = default;
};

/// True when every number of the state is finite.
inline bool isFinite(const FlightState& s)
{
    return std::isfinite(s.position.x) && std::isfinite(s.position.y) && std::isfinite(s.velocity.x) &&
           std::isfinite(s.velocity.y);
}

/// One point of a drawn path: where the bird was at a time.
struct TrackPoint
{
    double timeS = 0.0;
    Vec2 position; ///< m

    bool operator==(const TrackPoint&) const = default;
};

} // namespace abalike
