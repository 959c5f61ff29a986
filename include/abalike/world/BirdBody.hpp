#pragma once

#include <abalike/world/Catalog.hpp>

#include <string>

namespace abalike
{

/// Box2D simulates moving bodies of 0.1 m and more well: its contact skin (1 cm) and slop (5 mm) are tuned for them.
inline constexpr double kMinBirdBodyRadiusM = 0.05;
/// Box2D's solver degrades when a body rests on one more than ten times lighter (heavy on light).
inline constexpr double kMaxBirdMassRatio = 10.0;

/// The body a bird collides with in the world. Its flight before first contact always uses the bird's true mass and
/// size (the RK4 flight model drives it); only the collision body is clamped where Box2D would misbehave: a circle of
/// at least kMinBirdBodyRadiusM, and a mass of at most kMaxBirdMassRatio x the lightest block or pig of the level
/// (a light bird keeps its mass: light on heavy is no trouble for the solver, as the stacking check also assumes).
struct BirdBody
{
    double radiusM = 0.0;     ///< radius of the collision circle
    double massKg = 0.0;      ///< mass Box2D collides with
    double trueRadiusM = 0.0; ///< the bird's own radius (flight, drag)
    double trueMassKg = 0.0;  ///< the bird's own mass (flight, drag)
    double massLimitKg = 0.0; ///< kMaxBirdMassRatio x the lightest body; 0 when the level has none

    bool radiusClamped() const { return radiusM != trueRadiusM; }
    bool massClamped() const { return massKg != trueMassKg; }
    bool clamped() const { return radiusClamped() || massClamped(); }
};

/// The collision body of a bird in a level whose lightest block or pig weighs lightestBodyKg (0: none).
BirdBody birdCollisionBody(const BirdType& bird, double lightestBodyKg);

/// What the world does instead, in a sentence for the player; empty when the body is the bird's own.
std::string describeBirdBody(const BirdBody& body);

} // namespace abalike
