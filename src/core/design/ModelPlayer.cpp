#include "design/ParallelFor.hpp"

#include <abalike/design/AimRange.hpp>
#include <abalike/design/ModelPlayer.hpp>
#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelFlight.hpp>
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

Rank rankOf(const GameSession& session)
{
    return {session.phase() == Phase::Won, -session.pigsRemaining(), session.score().total()};
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
    const BirdType* bird = catalog.findBird(level.birds.at(fired.size()));
    const SlingshotBand band = slingshotBand(level.slingshot, *bird, catalog);
    ScriptedShot best;
    std::optional<Rank> bestRank;
    for (double angle = kAimMinAngleDeg; angle <= kAimMaxAngleDeg + 1e-9; angle += kAngleStepDeg)
        for (const double share : kPullShares)
        {
            std::vector<ScriptedShot> shots = fired;
            shots.emplace_back(angle, band.atFraction(share).speedMps);
            const auto session = simulateShots(level, shots, catalog);
            if (simulations != nullptr)
                ++*simulations;
            const Rank rank = rankOf(*session);
            if (!bestRank || rank > *bestRank)
            {
                bestRank = rank;
                best = shots.back();
            }
        }
    return best;
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
    // Every run faces the same untouched level with its first bird: aim once.
    std::size_t firstSimulations = 0;
    const ScriptedShot first = modelPlayerShot(level, {}, catalog, &firstSimulations);
    std::vector<char> won(options.runs, 0);
    std::vector<int> scores(options.runs, 0);
    std::vector<std::size_t> simulations(options.runs, 0);
    parallelFor(
        options.runs, workerCount(options.threads),
        [&](std::size_t run)
        {
            SplitMix64 random(options.seed * 0x100000001B3ull + run);
            std::vector<ScriptedShot> fired;
            for (std::size_t b = 0; b < level.birds.size(); ++b)
            {
                ScriptedShot shot = b == 0 ? first : modelPlayerShot(level, fired, catalog, &simulations[run]);
                const BirdType* bird = catalog.findBird(level.birds[b]);
                const SlingshotBand band = slingshotBand(level.slingshot, *bird, catalog);
                const double share =
                    std::clamp(band.forSpeed(shot.speedMps).fraction + aim.pullSigma * normal(random), 0.0, 1.0);
                shot.angleDeg = std::clamp(shot.angleDeg + aim.angleSigmaDeg * normal(random), -90.0, 90.0);
                shot.speedMps = band.atFraction(share).speedMps;
                fired.push_back(shot);
                const auto session = simulateShots(level, fired, catalog);
                ++simulations[run];
                if (session->finished())
                {
                    won[run] = session->phase() == Phase::Won ? 1 : 0;
                    scores[run] = session->score().total();
                    break;
                }
            }
        },
        [&, done = std::size_t{0}](std::size_t) mutable
        {
            ++done;
            if (options.progress)
                options.progress(done, options.runs);
        });
    result.wins = static_cast<std::size_t>(std::count(won.begin(), won.end(), 1));
    for (std::size_t run = 0; run < options.runs; ++run)
        if (won[run] != 0)
            result.winScores.push_back(scores[run]);
    result.simulations = firstSimulations;
    for (const std::size_t s : simulations)
        result.simulations += s;
    result.winShare = static_cast<double>(result.wins) / static_cast<double>(result.runs);
    const auto [low, high] = wilsonInterval90(result.wins, result.runs);
    result.low90 = low;
    result.high90 = high;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace abalike
