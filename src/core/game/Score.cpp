#include <abalike/game/Score.hpp>
#include <algorithm>
#include <cmath>

namespace abalike
{

int starsFor(int score, bool won, const std::array<int, 3>& thresholds)
{
    if (!won)
        return 0;
    int stars = 1; // winning is always worth one star
    if (score >= thresholds[1])
        stars = 2;
    if (score >= thresholds[2])
        stars = 3;
    return stars;
}

int accuracyPointsFor(double deviationM, int fullPoints, double toleranceM)
{
    if (!(deviationM >= 0.0) || !(toleranceM > 0.0))
        return 0;
    const double points = fullPoints * std::max(0.0, 1.0 - deviationM / toleranceM);
    return kAccuracyStepPoints * static_cast<int>(std::lround(points / kAccuracyStepPoints));
}

} // namespace abalike
