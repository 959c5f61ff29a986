#pragma once

#include <abalike/level/LevelDef.hpp>
#include <abalike/world/RestFindings.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace abalike
{

class Catalog;

/// A round body (a circle block or a pig) moved to where it rests as Science Birds' flat-bottomed one does.
struct SeatedBody
{
    bool pig = false;
    std::size_t index = 0;  ///< into level.pigs or level.blocks
    std::string support;    ///< "terrain 1", "block 2 (wood)"; "block 0 (wood) and block 1 (wood)" for a gap
    double distanceM = 0.0; ///< how far its centre was past the support's edge, or the gap's width
    double dxM = 0.0;       ///< how far it moved (> 0: right, up)
    double dyM = 0.0;

    std::string pointer() const { return (pig ? "/pigs/" : "/blocks/") + std::to_string(index); }
};

/// What a block (blocks[index]) or a pig (pigs[index]) stands on as supportUnder finds it, except that a round body
/// over a gap (between two planks, past an edge) stands on what its Science Birds flat bottom reaches.
SupportGap supportUnderFlatBottom(const LevelDef& level, const Catalog& catalog, bool pig, int index);

/// Science Birds' circles and pigs are polygons with a flat bottom reaching at least 0.4 of their radius each side of
/// the centre (its Circle: 34 cm of 80 across), so they stand with their centre a little past a platform's edge,
/// where our round bodies roll off. Each round body whose centre is over nothing it could rest on, while its flat
/// bottom would reach one support within snapM below or above it, is moved sideways until its centre is 2 cm inside
/// that support's edge. Positions stay on the millimetre.
std::vector<SeatedBody> seatRoundBodiesOnFlats(LevelDef& level, const Catalog& catalog, double snapM);

/// A round body whose centre is over a gap narrower than it between two supports it reaches (a pig across two
/// planks laid end to end) settles into the gap: it is set centred over it, touching both edges, so that it does
/// not drop and roll there when the level starts. distanceM holds the gap's width.
std::vector<SeatedBody> settleRoundBodiesIntoGaps(LevelDef& level, const Catalog& catalog, double snapM);

} // namespace abalike
