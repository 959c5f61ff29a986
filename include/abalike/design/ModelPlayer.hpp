#pragma once

#include <abalike/design/Solver.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace abalike
{

/// How the model player plays and how many times.
struct ModelPlayerOptions
{
    std::size_t runs = 40; ///< plays of the level; run i draws its aim errors from its own seed (seed, i)
    std::uint64_t seed = 1;
    /// The number of the first run: a measurement made in parts (runs 0-3 for a first estimate, then 4-39) joined
    /// with joinDifficulty equals one measurement of all the runs.
    std::size_t firstRun = 0;
    /// The first bird's aim, when an earlier part has made it (PlayerDifficulty::firstShot).
    std::optional<ScriptedShot> firstShot;
    int threads = 0; ///< 0: every hardware thread
    ProgressCallback progress;
};

/// A level's difficulty as a player finds it: the share of the model player's runs that win.
struct PlayerDifficulty
{
    std::size_t runs = 0;
    std::size_t wins = 0;
    double winShare = 0.0;
    double low90 = 0.0; ///< 90 % interval of the win rate (Wilson score interval)
    double high90 = 0.0;
    std::vector<int> winScores;  ///< the score of every winning run, in run order (star thresholds come from these)
    std::size_t simulations = 0; ///< headless games played in all
    double seconds = 0.0;
    std::optional<ScriptedShot> firstShot; ///< the first bird's aim, the same for every run (made once)
};

/// Runs in `check --solve`'s first estimate of difficulty, made before the solver (two rounds of two cores).
inline constexpr std::size_t kFirstEstimateRuns = 4;

/// The options for the runs after a first part measured with `options`, up to `totalRuns` in all: the next run
/// numbers and the first part's first aim.
ModelPlayerOptions runsAfter(ModelPlayerOptions options, const PlayerDifficulty& first, std::size_t totalRuns);

/// The measurement of runs a..b-1 and that of runs b..c-1 (ModelPlayerOptions::firstRun) as one of runs a..c-1.
PlayerDifficulty joinDifficulty(const PlayerDifficulty& first, const PlayerDifficulty& next);

/// The 90 % Wilson score interval of a win rate: {low, high}.
std::array<double, 2> wilsonInterval90(std::size_t wins, std::size_t runs);

/// The next shot the model player aims for, given the shots already fired: its search budget is every angle from
/// -10 to 80 degrees in 5 degree steps at 60, 80 and 100 % of the bird's full pull (57 candidates, no abilities),
/// each played headless after the shots so far (as simulateShots would; a SessionBranch goes on from the world as it
/// now is), ranked won, then fewer pigs left, then score, then candidate order.
ScriptedShot modelPlayerShot(const LevelDef& level, const std::vector<ScriptedShot>& fired, const Catalog& catalog,
                             std::size_t* simulations = nullptr);

/// Plays the level `runs` times as the model player: for each bird in turn it takes modelPlayerShot and launches
/// it with aiming noise (the catalog's model_player: normal errors of the angle and the pull); a run wins when the
/// level is won. Deterministic for a seed, whatever the number of threads.
PlayerDifficulty measurePlayerDifficulty(const LevelDef& level, const Catalog& catalog = Catalog::builtin(),
                                         const ModelPlayerOptions& options = {});

} // namespace abalike
