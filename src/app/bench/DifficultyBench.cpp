// `abalike bench difficulty`: how long `check --solve` takes to measure a level's difficulty (issue 56): the rest
// test, the model player's first runs (the first estimate), the solver, the other runs and the star thresholds,
// level by level over the campaign. Targets: the first estimate within 10 s, a median of at most 30 s and a maximum
// of at most 90 s on an idle 2-core machine. --no-copies plays every search
// trial from the level's start instead of on a copy of the process (SessionBranch), for a ratio in the same run.

#include "bench/BenchSuite.hpp"
#include "bench/ReportTable.hpp"
#include "shell/DataPaths.hpp"

#include <abalike/design/ModelPlayer.hpp>
#include <abalike/design/Solver.hpp>
#include <abalike/design/StarThresholds.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/util/ProcessCopy.hpp>
#include <abalike/world/RestCheck.hpp>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <sstream>

namespace abalike::app
{

namespace
{

constexpr double kMedianTargetS = 30.0;
constexpr double kMaxTargetS = 90.0;
constexpr double kFirstEstimateTargetS = 10.0;
/// --quick: three levels of growing size, ten runs of the model player.
const char* const kQuickLevels[] = {"1-1", "2-8", "4-8"};

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Timing
{
    std::string id;
    std::size_t bodies = 0;
    std::size_t birds = 0;
    double restS = 0.0;
    double solverS = 0.0;
    double playerS = 0.0;
    double firstEstimateS = 0.0; ///< from the start to the first estimate (the rest test and the first runs)
    std::size_t games = 0;
    std::string stars;

    double totalS() const { return restS + solverS + playerS; }
};

/// What `check --solve` does for one level, in its order, timed part by part: the rest test, the model player's
/// first runs (the first estimate), the solver, the other runs.
Timing measure(const LevelDef& level, std::size_t runs)
{
    Timing t;
    t.id = level.id;
    t.bodies = level.blocks.size() + level.pigs.size();
    t.birds = level.birds.size();
    const auto start = std::chrono::steady_clock::now();
    auto partStart = start;
    const RestReport rest = checkRest(level);
    t.restS = secondsSince(partStart);
    if (!rest.passed() || level.pigs.empty())
        return t;
    // check's order: the model player's first runs (the first estimate), the solver, the other runs.
    partStart = std::chrono::steady_clock::now();
    ModelPlayerOptions options;
    options.runs = std::min(runs, kFirstEstimateRuns);
    const PlayerDifficulty first = measurePlayerDifficulty(level, Catalog::builtin(), options);
    t.playerS = secondsSince(partStart);
    t.firstEstimateS = secondsSince(start);
    partStart = std::chrono::steady_clock::now();
    const Solution solution = solveLevel(level);
    t.solverS = secondsSince(partStart);
    t.games = solution.simulations + first.simulations;
    if (!solution.outcome.won)
        return t;
    partStart = std::chrono::steady_clock::now();
    const PlayerDifficulty player =
        joinDifficulty(first, measurePlayerDifficulty(level, Catalog::builtin(), runsAfter(options, first, runs)));
    t.playerS += secondsSince(partStart);
    t.games = solution.simulations + player.simulations;
    const auto stars = recommendedStars(player, solution.outcome.score);
    t.stars = std::to_string(stars[0]) + " / " + std::to_string(stars[1]) + " / " + std::to_string(stars[2]);
    return t;
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n == 0 ? 0.0 : n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2.0;
}

std::string seconds(double value)
{
    return formatSignificant(value, 3);
}

} // namespace

int runDifficultyBench(const BenchOptions& options)
{
    allowProcessCopies(!options.noCopies);
    const std::size_t runs = options.quick ? 10 : ModelPlayerOptions{}.runs;
    std::vector<LevelDef> levels;
    for (const std::string& path : loadCampaign(campaignManifest()))
    {
        LevelDef level = loadLevel(path, Catalog::builtin());
        const auto wanted = [&](const std::string& id)
        {
            if (!options.scenes.empty())
                return std::find(options.scenes.begin(), options.scenes.end(), id) != options.scenes.end();
            return !options.quick ||
                   std::find(std::begin(kQuickLevels), std::end(kQuickLevels), id) != std::end(kQuickLevels);
        };
        if (wanted(level.id))
            levels.push_back(std::move(level));
    }
    for (const std::string& scene : options.scenes)
        if (std::none_of(levels.begin(), levels.end(), [&](const LevelDef& l) { return l.id == scene; }))
        {
            std::cerr << "bench difficulty: no campaign level \"" << scene
                      << "\" (expected a campaign level id such as 1-3)\n";
            return 2;
        }
    ReportTable table({"level", "bodies", "birds", "first estimate s", "rest s", "solver s", "model player s",
                       "total s", "games", "recommended stars"});
    std::vector<double> totals;
    std::vector<double> firsts;
    for (const LevelDef& level : levels)
    {
        const Timing t = measure(level, runs);
        totals.push_back(t.totalS());
        firsts.push_back(t.firstEstimateS);
        table.addRow({t.id, std::to_string(t.bodies), std::to_string(t.birds), seconds(t.firstEstimateS),
                      seconds(t.restS), seconds(t.solverS), seconds(t.playerS), seconds(t.totalS()),
                      std::to_string(t.games), t.stars});
        std::cerr << t.id << ": " << seconds(t.totalS()) << " s\n";
    }
    const double mid = median(totals);
    const double most = totals.empty() ? 0.0 : *std::max_element(totals.begin(), totals.end());
    const double firstMost = firsts.empty() ? 0.0 : *std::max_element(firsts.begin(), firsts.end());
    const bool met = mid <= kMedianTargetS && most <= kMaxTargetS && firstMost <= kFirstEstimateTargetS;
    std::ostringstream summary;
    summary << "check --solve over " << levels.size() << " level(s), " << runs << " model player runs each, "
            << (options.noCopies ? "every trial replayed from the start" : "trials on process copies") << ": median "
            << seconds(mid) << " s (target <= " << kMedianTargetS << "), max " << seconds(most)
            << " s (target <= " << kMaxTargetS << "); first estimate at most " << seconds(firstMost)
            << " s (target <= " << kFirstEstimateTargetS << "): " << (met ? "met" : "NOT met") << ". "
            << loadAverageNote() << "\n";
    std::cout << table.text() << summary.str();
    const std::string name = options.noCopies ? "difficulty-no-copies" : "difficulty";
    const bool written = writeReportFile(options.outDir, name + ".md", table.markdown() + "\n" + summary.str()) &&
                         writeReportFile(options.outDir, name + ".csv", table.csv());
    return written ? 0 : 1;
}

} // namespace abalike::app
