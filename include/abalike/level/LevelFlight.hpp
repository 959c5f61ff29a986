#pragma once

#include <abalike/flight/FlightModel.hpp>
#include <abalike/level/LevelDef.hpp>
#include <abalike/level/SlingshotBand.hpp>
#include <abalike/world/Catalog.hpp>
#include <string>

namespace abalike
{

/// The flight model acting on a bird in a level's environment: gravity, quadratic drag from the air density and
/// the bird's size (absent in vacuum), and the wind and gusts that act through that drag.
FlightModel levelFlightModel(const EnvironmentDef& environment, const BirdType& bird);

/// The catalog's slingshot with the force of the level's world (levelTheme), whatever the level sets itself.
BandDef worldBand(const LevelDef& level, const Catalog& catalog);

/// The band a level's slingshot has: the catalog's slingshot with the force of the level's world (levelTheme), each
/// number the level sets itself replacing the catalog's.
BandDef levelBand(const LevelDef& level, const Catalog& catalog);

/// What `check` warns about a level with a band of its own, naming what it sets against its world's band; empty for
/// a level that uses its world's.
std::string ownBandWarning(const LevelDef& level, const Catalog& catalog);

/// The level's band launching a bird, with the catalog's launch-speed cap.
SlingshotBand slingshotBand(const LevelDef& level, const BirdType& bird, const Catalog& catalog);

/// Fastest launch of a bird from a level's slingshot: a full pull, v0 = sqrt(F_max x_max / (m + m_b)), capped at the
/// catalog's launch-speed cap (Catalog::maxLaunchSpeedMps): the one cap the game, the level checks, the solver and the
/// HUD use.
double maxLaunchSpeed(const LevelDef& level, const BirdType& bird, const Catalog& catalog);

} // namespace abalike
