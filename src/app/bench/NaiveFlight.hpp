#pragma once

#include <abalike/game/ReferenceShots.hpp>

#include <optional>

namespace abalike::app
{

/// How the naive world starts and steps the bird.
struct NaiveFlightSettings
{
    int stepsPerFrame = 1;      ///< Box2D steps per 1/60 s (4: 240 Hz)
    bool halfStepStart = false; ///< start from v0 - a0 h / 2, which removes the vacuum drift of Box2D's scheme
};

/// Where a bird flown the common Box2D way first touches the reference shot's level: a raw b2World with the same
/// geometry (and the same skin compensation) as GameWorld, gravity set on the world, drag and wind applied as a
/// force each step, the launch velocity set on the body. Box2D then integrates by semi-implicit Euler in float and
/// caps a body at b2_maxTranslation per step. Nullopt if nothing is touched within 20 s.
std::optional<FlightState> naiveFirstContact(const ReferenceShot& shot, const NaiveFlightSettings& settings);

} // namespace abalike::app
