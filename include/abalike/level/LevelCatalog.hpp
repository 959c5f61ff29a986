#pragma once

#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Catalog.hpp>

namespace abalike
{

/// The bird type of a level's custom bird: its mass, size and drag, no ability, a catalog bird's friction and bounce.
BirdType customBirdType(const CustomBirdDef& bird);

/// The catalog as a level sees it: the base table with the level's material overrides applied and its custom bird
/// added. The world, the session, the checks and the solver all read a level's numbers through this one function.
Catalog levelCatalog(const LevelDef& level, const Catalog& base);

} // namespace abalike
