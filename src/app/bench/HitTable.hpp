#pragma once

#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Entity.hpp>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace abalike::app
{

/// `bench feel`'s hit table (issue 57): over the campaign grid (every level, 0-60 deg in 2 deg steps, 70, 85 and
/// 100 % pull, each bird the level has as its first bird), a *strike* is the bird's first contact when it is a
/// block, a *break* is that block destroyed within 0.5 s of the contact, and the bird *keeps going* when its
/// horizontal velocity after the break step has the sign it had before the contact. The black bird is played twice:
/// flying into the block, and blasting the moment it touches it.
struct HitCounts
{
    int strikes = 0;
    int breaks = 0;
    int keepsGoing = 0;
};

struct HitTable
{
    /// (bird, or "black (blast at contact)"; material) -> counts
    std::map<std::pair<std::string, std::string>, HitCounts> counts;
    /// The same strikes by the piece struck (strikePiece): (bird, material, piece) -> counts
    std::map<std::tuple<std::string, std::string, std::string>, HitCounts> byPiece;
    int shots = 0;
};

/// What kind of piece a strike met, as the player tells them apart: "roof" (a plank lying flat, struck from above),
/// "plank end" (a flat plank struck on its end or underside), "post" (standing: at least twice as tall as wide),
/// "hollow box", or "block" (everything else: squares, circles, triangles).
std::string strikePiece(const Entity& block, double contactY);

/// angleStepDeg: 2 for the full grid, larger for a quick sample.
HitTable measureHits(const std::vector<LevelDef>& levels, int angleStepDeg);

/// The table with the targets and counter-targets marked met or missed.
std::string hitTableMarkdown(const HitTable& table);

} // namespace abalike::app
