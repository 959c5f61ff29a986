#pragma once

#include <array>

namespace abalike
{

/// Where a level's score came from; the results panel shows each line.
struct ScoreBreakdown
{
    int blockPoints = 0;
    int pigPoints = 0;
    int unusedBirdBonus = 0;
    int accuracyBonus = 0;
    int blocksDestroyed = 0;
    int pigsDefeated = 0;

    int total() const { return blockPoints + pigPoints + unusedBirdBonus + accuracyBonus; }
};

/// Stars earned: 0 when the level was lost, otherwise how many thresholds the score reaches (at least 1).
int starsFor(int score, bool won, const std::array<int, 3>& thresholds);

} // namespace abalike
