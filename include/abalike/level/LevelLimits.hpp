#pragma once

#include <cstddef>

namespace abalike::limits
{

// What the loader accepts. levels/schema/level.schema.json states the same numbers; change both together.

/// Box2D simulates moving bodies of 0.1 to 10 m and static ones up to 50 m well, within about 2 km of the origin.
inline constexpr double kMinBodySizeM = 0.1;
inline constexpr double kMaxMovingSizeM = 10.0;
inline constexpr double kMaxStaticSizeM = 50.0;
inline constexpr double kWorldExtentM = 2000.0;

/// Bodies may touch; they overlap when they interpenetrate by more than this (m).
inline constexpr double kOverlapToleranceM = 0.01;

inline constexpr double kMaxAngleDeg = 360.0;
inline constexpr double kMinForceN = 1.0;
inline constexpr double kMaxForceN = 1.0e6;
/// The slingshot's full pull: a hand catapult's 0.1 m to a siege engine's 10 m.
inline constexpr double kMinPullM = 0.1;
inline constexpr double kMaxPullM = 10.0;
/// The band's moving mass: 0 (massless) to a siege engine's arm.
inline constexpr double kMaxBandMassKg = 1000.0;
inline constexpr double kMaxGravity = 100.0;    // m/s^2; Jupiter is 24.79
inline constexpr double kMaxAirDensity = 100.0; // kg/m^3; Venus's surface is about 65
inline constexpr double kMaxWindMps = 100.0;
inline constexpr double kMinGustPeriodS = 0.1;
inline constexpr double kMaxGustPeriodS = 3600.0;
inline constexpr double kMaxGustTimeS = 3600.0;
inline constexpr double kMinTimeLimitS = 1.0;
inline constexpr double kMaxTimeLimitS = 3600.0;
inline constexpr long long kMaxStarScore = 100000000;

/// A level's own material values ("materials"): balsa is about 150 kg/m^3, osmium 22 590; rubber on rubber reaches a
/// friction of about 1.2.
inline constexpr double kMinMaterialDensity = 50.0;
inline constexpr double kMaxMaterialDensity = 25000.0;
inline constexpr double kMaxFriction = 2.0;
inline constexpr double kMinStrengthNs = 1.0;
inline constexpr double kMaxStrengthNs = 1.0e6;

/// A custom bird: PhET Projectile Motion Lab's ranges. Outside what Box2D simulates well the world collides it as a
/// clamped body (world/BirdBody.hpp); its flight always uses these values.
inline constexpr double kMinBirdMassKg = 0.01;
inline constexpr double kMaxBirdMassKg = 5000.0;
inline constexpr double kMinBirdDiameterM = 0.01;
inline constexpr double kMaxBirdDiameterM = 3.0;
inline constexpr double kMinDragCoefficient = 0.04;
inline constexpr double kMaxDragCoefficient = 1.2;

inline constexpr std::size_t kMaxBirds = 20;
inline constexpr std::size_t kMaxBlocks = 1000;
inline constexpr std::size_t kMaxPigs = 100;
inline constexpr std::size_t kMaxTerrain = 200;
inline constexpr std::size_t kMaxTerrainPoints = 256; ///< corners of one terrain polygon
inline constexpr std::size_t kMaxHints = 20;
inline constexpr std::size_t kMaxClaims = 40;
inline constexpr std::size_t kMaxGustSteps = 100;

/// A large level is a few kB; a level nests 4 deep.
inline constexpr std::size_t kMaxLevelBytes = 4u << 20;
inline constexpr int kMaxNesting = 64;

} // namespace abalike::limits
