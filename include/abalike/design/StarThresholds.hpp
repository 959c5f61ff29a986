#pragma once

#include <abalike/design/ModelPlayer.hpp>
#include <array>

namespace abalike
{

/// The nearest-rank quantile of the winning scores that three stars ask for.
inline constexpr double kThreeStarQuantile = 0.8;

/// The star thresholds a level should have, from how the model player wins it (levels/README.md, "Difficulty"):
/// one star for any win (its lowest winning score), two for the median winning score, three for the 80th percentile
/// (nearest rank), each rounded down to 100 points: at least half of the winning runs reach two stars and a fifth
/// three. A level the model player never wins takes the solver's best score for two and three stars and half of it for
/// one. `abalike check --solve` recommends them and `--write-stars` writes them; tools/balance-campaign does so for
/// the whole campaign.
std::array<int, 3> recommendedStars(const PlayerDifficulty& player, int solverScore);

} // namespace abalike
