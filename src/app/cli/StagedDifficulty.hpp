#pragma once

#include <abalike/design/ModelPlayer.hpp>

#include <chrono>
#include <optional>
#include <ostream>
#include <string>

namespace abalike::app
{

/// The model player's runs for `check --solve`, in two parts: a few runs first, whose estimate is printed at once
/// (a designer has difficulty and stars within seconds, before the solver), then the others. Joined, the parts are
/// one measurement of all the runs, bit for bit (ModelPlayerOptions::firstRun).
class StagedDifficulty
{
public:
    StagedDifficulty(const LevelDef& level, std::size_t runs, int threads);

    /// Plays the first part and prints its estimate as one line on out; nothing when no run is asked for.
    void estimate(std::ostream& out);

    /// Plays the other runs and gives the measurement of all of them.
    PlayerDifficulty finish();

private:
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
