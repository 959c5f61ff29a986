#pragma once

#include <abalike/design/Solver.hpp>

#include <cstdint>

namespace abalike
{

/// How a level fares against random play: the campaign is ordered by winShare, easiest first.
struct Difficulty
{
    std::size_t samples = 0;
    std::size_t wins = 0;
    double winShare = 0.0; ///< wins / samples
    double pigShare = 0.0; ///< mean share of the pigs defeated, to rank levels that random play never wins
    double seconds = 0.0;
};

/// Plays `samples` random full shot sequences -- every bird of the level shot at an angle uniform in 0..90
/// degrees and a speed uniform in 0..its top speed, no abilities -- and counts the wins. Sample i uses its own
/// generator seeded from (seed, i), so the result does not depend on the number of threads.
Difficulty measureDifficulty(const LevelDef& level, std::size_t samples, std::uint64_t seed = 1,
                             const Catalog& catalog = Catalog::builtin(), int threads = 0,
                             const ProgressCallback& progress = {});

} // namespace abalike
