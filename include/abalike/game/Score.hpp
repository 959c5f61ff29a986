#pragma once

#include <array>

namespace abalike
{

/// Where a level's score came from; the results panel shows each line.
struct ScoreBreakdown
{
    int blockPoints = 0;     ///< per destroyed block, by material
    int pigPoints = 0;       ///< per defeated pig, by type
    int unusedBirdBonus = 0; ///< efficiency: per bird left when the level is won
    int efficiencyBonus = 0; ///< efficiency: per pig beyond the first that one shot defeats
    int accuracyBonus = 0;   ///< accuracy: per shot whose first contact came where the preview said
    int blocksDestroyed = 0;
    int pigsDefeated = 0;
    int unusedBirds = 0;   ///< birds left when the level was won
    int accurateShots = 0; ///< shots that earned accuracy points

    int total() const { return blockPoints + pigPoints + unusedBirdBonus + efficiencyBonus + accuracyBonus; }
};

/// Accuracy points of one shot: full points for a first contact exactly at the predicted point, falling linearly
/// to zero at the tolerance, in steps of kAccuracyStepPoints (a contact 0.05 mm off is a perfect shot to the eye; three
/// of them read 3,000, not 2,999).
inline constexpr int kAccuracyStepPoints = 10;
int accuracyPointsFor(double deviationM, int fullPoints, double toleranceM);

/// Stars earned: 0 when the level was lost, otherwise how many thresholds the score reaches (at least 1).
int starsFor(int score, bool won, const std::array<int, 3>& thresholds);

} // namespace abalike
