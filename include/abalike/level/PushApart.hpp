#pragma once

#include <abalike/level/LevelDef.hpp>

#include <string>
#include <vector>

namespace abalike
{

class Catalog;

/// A body PushApart moved, and why.
struct PushedBody
{
    std::string pointer; ///< "/blocks/3", "/pigs/0"
    std::string other;   ///< the body it overlapped most ("/pigs/2", "/terrain/0")
    double depthM = 0.0; ///< how deep it overlapped that body
    double dxM = 0.0;    ///< how far it moved
    double dyM = 0.0;
};

/// Moves a level's blocks and pigs out of one another the way a physics engine's first step pushes them apart
/// (Science Birds relies on it: its files hold pigs sunk into pigs and planks sunk into posts). Bodies are taken from
/// the lowest up; one that overlaps terrain or a body taken before it more than toleranceM is lifted clear of it, or
/// pushed sideways when that body stands at its own height, or when sideways is the shorter way and leaves it
/// standing on something (a block a few centimetres into the pig beside it, a pig moved into a post); one that cannot
/// be lifted is lowered out of a body above it (a plank raised into the posts it carries; never into the ground),
/// else pushed sideways. Positions stay on the millimetre.
/// Returns the bodies moved, in the order they were; a body that cannot be freed within a metre (or its own height,
/// when it is taller) is left alone.
std::vector<PushedBody> pushApartOverlaps(LevelDef& level, const Catalog& catalog, double toleranceM);

/// Blocks and pigs that reach below the ground, set onto it (a physics engine pushes them out at its first step):
/// one entry each, other "the ground".
std::vector<PushedBody> pushOutOfGround(LevelDef& level, const Catalog& catalog);

/// How deep a block (blocks[index]) or a pig (pigs[index]) overlaps the deepest other body or terrain (m; 0: none).
double deepestOverlap(const LevelDef& level, const Catalog& catalog, bool pig, std::size_t index);

} // namespace abalike
