#pragma once

#include <abalike/level/LevelDef.hpp>
#include <string>
#include <vector>

namespace abalike::app
{

/// `bench feel`'s tower table (issue 57): over the campaign grid (every level, 0-60 deg, 70, 85 and 100 % pull, the
/// level's first bird), a shot *brings a tower down* when a block that stood at least 2 m above its tower's base falls
/// at least 1 m (or breaks at least 1 m lower); a *tower* is a group of blocks touching each other when the level
/// starts. The pigs whose centre is within 1 m of that tower's footprint (across) and below its top are *under or
/// beside* it; the table counts how many of them the shot defeats before the next bird is ready.
struct TowerCounts
{
    int shots = 0;        ///< shots played
    int towersDown = 0;   ///< shots that brought at least one tower down
    int pigsNear = 0;     ///< pigs under or beside a tower brought down, summed over those shots
    int pigsDefeated = 0; ///< of those, the ones defeated
};

struct TowerTable
{
    TowerCounts all;
    std::vector<std::pair<std::string, TowerCounts>> byEpisode; ///< in the campaign's order
};

/// angleStepDeg: 2 for the full grid, larger for a quick sample.
TowerTable measureTowers(const std::vector<LevelDef>& levels, int angleStepDeg);

/// The table with the target (>= 70 % of the pigs under or beside defeated) marked met or missed.
std::string towerTableMarkdown(const TowerTable& table);

} // namespace abalike::app
