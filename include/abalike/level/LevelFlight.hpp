#pragma once

#include <abalike/flight/FlightModel.hpp>
#include <abalike/level/LevelDef.hpp>
#include <abalike/level/SlingshotBand.hpp>
#include <abalike/world/Catalog.hpp>

namespace abalike
{

/// The flight model acting on a bird in a level's environment: gravity, quadratic drag from the air density and
/// the bird's size (absent in vacuum), and the wind and gusts that act through that drag.
FlightModel levelFlightModel(const EnvironmentDef& environment, const BirdType& bird);

/// The slingshot's band launching a bird, with the catalog's launch-speed cap.
SlingshotBand slingshotBand(const SlingshotDef& slingshot, const BirdType& bird, const Catalog& catalog);

/// Fastest launch of a bird from a slingshot: a full pull, v0 = sqrt(F_max x_max / m), capped at the catalog's
/// launch-speed cap (Catalog::maxLaunchSpeedMps): the one cap the game, the level checks, the solver and the HUD use.
double maxLaunchSpeed(const SlingshotDef& slingshot, const BirdType& bird, const Catalog& catalog);

} // namespace abalike
