#pragma once

#include <abalike/flight/FlightModel.hpp>
#include <abalike/level/LevelDef.hpp>

#include <optional>
#include <string>
#include <vector>

namespace abalike
{

/// A shot whose predicted and actual first contact are compared: vacuum, drag and wind, short flights into a wall
/// and long ones onto the ground. Defined once here; the tests, `abalike bench reference` and the docs use them.
struct ReferenceShot
{
    std::string name{};
    std::string description{};
    std::string bird = "red";
    double angleDeg = 45.0;
    double speedMps = 20.0;
    double gravity = 9.81;
    double airDensity = 0.0; ///< kg/m^3; 0 is vacuum
    double windX = 0.0;
    double windY = 0.0;
    std::optional<GustDef> gusts{};
    std::optional<double>
        wallX{}; ///< centre of a 0.4 m wide, 10 m high stone wall in the way; none: the flight ends on the ground
};

/// The fixed set of reference shots.
const std::vector<ReferenceShot>& referenceShots();

/// A level for one shot: flat ground at y = 0, the slingshot at (0, 1.5) strong enough for any speed the world
/// allows, the shot's environment and bird, and its wall; one pig sits far behind everything.
LevelDef referenceShotLevel(const ReferenceShot& shot);

} // namespace abalike
