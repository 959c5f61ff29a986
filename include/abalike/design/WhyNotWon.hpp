#pragma once

#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Catalog.hpp>
#include <string>

namespace abalike
{

/// Why a pig the solver's best try leaves standing is hard to get at, in words, from the level's first bird at full
/// pull: "out of reach (the nearest path passes 3.2 m from it)" when no launch angle's free flight comes within the
/// pig's and the bird's radii; "shielded by block 3 (stone), which takes 300 N·s, more than the red bird's 120" when
/// the launches whose free flight would reach it hit that block first; else the body they hit first, or "hit
/// directly it is not defeated". Empty for a level without birds or an index out of range.
std::string whyPigSurvives(const LevelDef& level, const Catalog& catalog, int pigIndex);

} // namespace abalike
