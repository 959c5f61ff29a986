#include <abalike/game/Score.hpp>

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

} // namespace abalike
