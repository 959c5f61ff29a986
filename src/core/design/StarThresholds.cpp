#include <abalike/design/StarThresholds.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace abalike
{

namespace
{

int hundreds(int score)
{
    return score / 100 * 100;
}

} // namespace

std::array<int, 3> recommendedStars(const PlayerDifficulty& player, int solverScore)
{
    std::vector<int> scores = player.winScores;
    if (scores.empty())
    {
        const int top = hundreds(solverScore);
        return {top / 200 * 100, top, top};
    }
    std::sort(scores.begin(), scores.end());
    const int median = scores[(scores.size() - 1) / 2]; // the lower median, as Python's median_low
    // The 80th percentile, so that at least a fifth of the winning runs reach three stars (issue 57).
    const auto rank = static_cast<std::size_t>(std::ceil(kThreeStarQuantile * static_cast<double>(scores.size())));
    const int p80 = scores[std::min(scores.size() - 1, rank == 0 ? 0 : rank - 1)];
    const int one = hundreds(scores.front());
    const int two = std::max(one, hundreds(median));
    return {one, two, std::max(two, hundreds(p80))};
}

} // namespace abalike
