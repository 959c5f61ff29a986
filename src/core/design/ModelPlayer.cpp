#include "design/ParallelFor.hpp"

#include <abalike/design/AimRange.hpp>
#include <abalike/design/ModelPlayer.hpp>
#include <abalike/game/GameSession.hpp>
#include <abalike/game/SessionBranch.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <abalike/util/Bytes.hpp>
#include <abalike/util/SplitMix64.hpp>
#include <abalike/world/RestCheck.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <tuple>

namespace abalike
{

namespace
{

constexpr double kAngleStepDeg = 5.0;
constexpr double kPullShares[] = {0.6, 0.8, 1.0};
constexpr double kZ90 = 1.6448536269514722; ///< two-sided 90 %

/// A standard normal number by Box-Muller (std::normal_distribution is not the same on every library).
double normal(SplitMix64& random)
{
    const double u = random.uniform();
    const double v = random.uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
}

using Rank = std::tuple<bool, int, int>; ///< won, -pigs left, score: larger is better

std::string rankBytes(const GameSession& session)
{
    return BytesOut()
        .put(session.phase() == Phase::Won)
        .put(-session.pigsRemaining())
        .put(session.score().total())
        .take();
}

Rank rankOf(const std::string& bytes)
{
    BytesIn in(bytes);
    const bool won = in.get<bool>();
    const int pigs = in.get<int>();
    return {won, pigs, in.get<int>()};
}

/// The model player's aim after the shots the branch has played (modelPlayerShot), its candidates played on up to
/// `threads` workers.
ScriptedShot bestShotFrom(const SessionBranch& branch, const LevelDef& level, const Catalog& catalog,
                          std::size_t* simulations, unsigned threads = 1)
{
    const BirdType* bird = catalog.findBird(level.birds.at(branch.shots().size()));
    const SlingshotBand band = slingshotBand(level, *bird, catalog);
    std::vector<ScriptedShot> candidates;
    for (double angle = kAimMinAngleDeg; angle <= kAimMaxAngleDeg + 1e-9; angle += kAngleStepDeg)
        for (const double share : kPullShares)
            candidates.emplace_back(angle, band.atFraction(share).speedMps);
    std::vector<Rank> ranks(candidates.size());
    parallelForBytes(
        candidates.size(), threads, [&](std::size_t i) { return branch.trial(candidates[i], rankBytes); },
        [&](std::size_t i, const std::string& bytes) { ranks[i] = rankOf(bytes); }, [](std::size_t) {});
    if (simulations != nullptr)
        *simulations += candidates.size();
    // The first of the best, in candidate order.
    std::size_t best = 0;
    for (std::size_t i = 1; i < ranks.size(); ++i)
        if (ranks[i] > ranks[best])
            best = i;
    return candidates[best];
}

/// How one run of the model player ended.
struct RunResult
{
    bool won = false;
    int score = 0;
    std::size_t simulations = 0;
};

/// The win share and its interval, from the wins and runs.
void setShare(PlayerDifficulty& d)
{
    d.winShare = d.runs == 0 ? 0.0 : static_cast<double>(d.wins) / static_cast<double>(d.runs);
    const auto [low, high] = wilsonInterval90(d.wins, d.runs);
    d.low90 = low;
    d.high90 = high;
}

} // namespace

std::array<double, 2> wilsonInterval90(std::size_t wins, std::size_t runs)
{
    if (runs == 0)
        return {0.0, 1.0};
    const double n = static_cast<double>(runs);
    const double p = static_cast<double>(wins) / n;
    const double z2 = kZ90 * kZ90;
    const double centre = (p + z2 / (2.0 * n)) / (1.0 + z2 / n);
    const double half = kZ90 * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n)) / (1.0 + z2 / n);
    return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

ScriptedShot modelPlayerShot(const LevelDef& level, const std::vector<ScriptedShot>& fired, const Catalog& catalog,
                             std::size_t* simulations)
{
    return bestShotFrom(SessionBranch(level, fired, catalog), level, catalog, simulations);
}

PlayerDifficulty measurePlayerDifficulty(const LevelDef& level, const Catalog& catalog,
                                         const ModelPlayerOptions& options)
{
    const auto start = std::chrono::steady_clock::now();
    PlayerDifficulty result;
    result.runs = options.runs;
    if (options.runs == 0 || level.birds.empty() || level.pigs.empty())
        return result;
    // A level whose pigs fall by themselves is not the player's to win (as for the solver).
    for (const BodyRest& body : checkRest(level, catalog).bodies)
        if (body.kind == EntityKind::Pig && (body.destroyed || body.damaged))
            return result;

    const PlayerAim& aim = catalog.playerAim();
    // Every run faces the same untouched level with its first bird: aim once (a later part of the measurement has
    // the aim from the first part, and its games are counted there).
    std::size_t firstSimulations = 0;
    if (!options.firstShot)
        result.firstShot = bestShotFrom(SessionBranch(level, {}, catalog), level, catalog, &firstSimulations,
                                        workerCount(options.threads));
    else
        result.firstShot = options.firstShot;
    const ScriptedShot first = *result.firstShot;
    std::vector<RunResult> runs(options.runs);
    parallelForBytes(
        options.runs, workerCount(options.threads),
        [&](std::size_t run)
        {
            RunResult outcome;
            SplitMix64 random(options.seed * 0x100000001B3ull + options.firstRun + run);
            SessionBranch game(level, {}, catalog); // the run's own game, played on shot by shot
            for (std::size_t b = 0; b < level.birds.size(); ++b)
            {
                ScriptedShot shot = b == 0 ? first : bestShotFrom(game, level, catalog, &outcome.simulations);
                const BirdType* bird = catalog.findBird(level.birds[b]);
                const SlingshotBand band = slingshotBand(level, *bird, catalog);
                const double share =
                    std::clamp(band.forSpeed(shot.speedMps).fraction + aim.pullSigma * normal(random), 0.0, 1.0);
                shot.angleDeg = std::clamp(shot.angleDeg + aim.angleSigmaDeg * normal(random), -90.0, 90.0);
                shot.speedMps = band.atFraction(share).speedMps;
                game.play(shot);
                ++outcome.simulations;
                if (const GameSession& session = game.session(); session.finished())
                {
                    outcome.won = session.phase() == Phase::Won;
                    outcome.score = session.score().total();
                    break;
                }
            }
            return BytesOut().put(outcome).take();
        },
        [&](std::size_t run, const std::string& bytes) { runs[run] = BytesIn(bytes).get<RunResult>(); },
        [&, done = std::size_t{0}](std::size_t) mutable
        {
            ++done;
            if (options.progress)
                options.progress(done, options.runs);
        });
    result.simulations = firstSimulations;
    for (const RunResult& run : runs)
    {
        result.wins += run.won ? 1 : 0;
        if (run.won)
            result.winScores.push_back(run.score);
        result.simulations += run.simulations;
    }
    setShare(result);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

ModelPlayerOptions runsAfter(ModelPlayerOptions options, const PlayerDifficulty& first, std::size_t totalRuns)
{
    options.firstRun += first.runs;
    options.runs = totalRuns > options.firstRun ? totalRuns - options.firstRun : 0;
    options.firstShot = first.firstShot;
    return options;
}

PlayerDifficulty joinDifficulty(const PlayerDifficulty& first, const PlayerDifficulty& next)
{
    PlayerDifficulty joined = first;
    joined.runs += next.runs;
    joined.wins += next.wins;
    joined.winScores.insert(joined.winScores.end(), next.winScores.begin(), next.winScores.end());
    joined.simulations += next.simulations;
    joined.seconds += next.seconds;
    if (!joined.firstShot)
        joined.firstShot = next.firstShot;
    setShare(joined);
    return joined;
}

} // namespace abalike
