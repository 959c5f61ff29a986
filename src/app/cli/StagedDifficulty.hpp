#pragma once

#include <abalike/design/ModelPlayer.hpp>

#include <chrono>
#include <optional>
#include <ostream>
#include <string>

namespace abalike::app
{

/// The model player's runs for `check --solve`, in parts: a few runs first, whose estimate is printed at once (a
/// designer has difficulty and stars within seconds, before the solver), then the others a dozen at a time, each part
/// refining the estimate on its own line. Joined, the parts are one measurement of all the runs, bit for bit
/// (ModelPlayerOptions::firstRun).
class StagedDifficulty
{
public:
    StagedDifficulty(const LevelDef& level, std::size_t runs, int threads);

    /// Plays the first part and prints its estimate as one line on out; nothing when no run is asked for.
    void estimate(std::ostream& out);

    /// Plays the other runs, printing the estimate refined after each part but the last on out, and gives the
    /// measurement of all of them.
    PlayerDifficulty finish(std::ostream& out);

    /// Runs played between two refined estimates.
    static constexpr std::size_t kRefineRuns = 12;

private:
    /// "6-5: first estimate (4 of 40 model player runs, 6.6 s): 0 won (0 %, 90 % interval 0-40 %)[, stars about ...]"
    std::string describe(const std::string& what, const PlayerDifficulty& sofar) const;
    PlayerDifficulty play(const ModelPlayerOptions& options, const std::string& label);
    /// The options of the first `runs` runs.
    ModelPlayerOptions firstRuns(std::size_t runs) const;

    const LevelDef& m_level;
    std::size_t m_runs;
    int m_threads;
    std::chrono::steady_clock::time_point m_start;
    std::optional<PlayerDifficulty> m_first;
};

} // namespace abalike::app
