#include "bench/BenchSuite.hpp"
#include "bench/ReportTable.hpp"
#include "shell/DataPaths.hpp"

#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>

namespace abalike::app
{

namespace
{

constexpr int kShots = 10000;
constexpr int kQuickShots = 500;
constexpr int kSampleEvery = 250;          ///< shots between two rows of soak.csv
constexpr double kMaxGrowth = 0.05;        ///< resident memory may grow 5% from the start to the end
constexpr std::uint64_t kSeed = 20240601u; ///< same shots on every run
constexpr double kMinAngleDeg = -10.0;
constexpr double kMaxAngleDeg = 80.0;
constexpr double kMinSpeedShare = 0.2; ///< of the bird's maximum launch speed

/// What the soak did, for the report.
struct SoakTally
{
    int shots = 0;
    int games = 0;
    int won = 0;
    int lost = 0;
    int nonFinite = 0; ///< shots after which a body had a NaN or infinite position or velocity
    double simSeconds = 0.0;
    std::vector<std::array<double, 3>> samples; ///< (shots, wall s, VmRSS kB)
};

/// Plays one game of level with random shots until it is over or the soak has fired all its shots.
void playGame(GameSession& session, int totalShots, std::mt19937_64& rng, SoakTally& tally)
{
    std::uniform_real_distribution<double> angle(kMinAngleDeg, kMaxAngleDeg);
    std::uniform_real_distribution<double> speedShare(kMinSpeedShare, 1.0);
    while (!session.finished() && tally.shots < totalShots)
    {
        while (session.phase() == Phase::Flying)
            session.step();
        if (session.finished())
            break;
        session.launch(angle(rng), speedShare(rng) * session.maxLaunchSpeed());
        ++tally.shots;
        while (session.phase() == Phase::Flying)
            session.step();
        if (session.world().hasNonFiniteState())
            ++tally.nonFinite;
    }
    ++tally.games;
    tally.won += session.phase() == Phase::Won ? 1 : 0;
    tally.lost += session.phase() == Phase::Lost ? 1 : 0;
    tally.simSeconds += session.simTime();
}

std::string megabytes(long kb)
{
    std::ostringstream text;
    text << std::fixed << std::setprecision(1) << static_cast<double>(kb) / 1024.0 << " MB";
    return kb < 0 ? "n/a" : text.str();
}

} // namespace

int runSoakBench(const BenchOptions& options)
{
    const int totalShots = options.quick ? kQuickShots : kShots;
    const long rssBeforeKb = residentKb();
    std::vector<LevelDef> levels;
    for (const std::string& path : loadCampaign(campaignManifest()))
        levels.push_back(loadLevel(path, Catalog::builtin()));
    if (levels.empty())
    {
        std::cerr << "abalike: error: bench soak: the campaign has no levels\n";
        return 1;
    }

    std::mt19937_64 rng(kSeed);
    SoakTally tally;
    const auto start = std::chrono::steady_clock::now();
    const auto wallSeconds = [&]
    {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    // One game per level first: the allocator's pools and Box2D's block allocator reach their working size there.
    // Growth is measured from that point, so what is left is what 10 000 shots add.
    for (const LevelDef& level : levels)
    {
        GameSession session(level);
        playGame(session, totalShots, rng, tally);
    }
    const long rssStartKb = residentKb();
    const int warmUpShots = tally.shots;
    tally.samples.push_back({static_cast<double>(tally.shots), wallSeconds(), static_cast<double>(rssStartKb)});

    // Each level is played as a new session, then restarted and played again: both ways of starting are soaked.
    std::unique_ptr<GameSession> session;
    int nextSample = tally.shots + kSampleEvery;
    for (std::size_t game = 0; tally.shots < totalShots; ++game)
    {
        if (game % 2 == 0)
            session = std::make_unique<GameSession>(levels[(game / 2) % levels.size()]);
        else
            session->restart();
        playGame(*session, totalShots, rng, tally);
        if (tally.shots >= nextSample || tally.shots >= totalShots)
        {
            tally.samples.push_back(
                {static_cast<double>(tally.shots), wallSeconds(), static_cast<double>(residentKb())});
            nextSample += kSampleEvery;
        }
    }
    session.reset();
    const long rssEndKb = residentKb();
    const double seconds = wallSeconds();
    const double growth =
        rssStartKb > 0 ? static_cast<double>(rssEndKb - rssStartKb) / static_cast<double>(rssStartKb) : 0.0;
    const bool pass = rssStartKb < 0 || growth <= kMaxGrowth;

    std::ostringstream table;
    table << std::fixed << std::setprecision(1);
    table << "| | |\n|---|---|\n"
          << "| shots | " << tally.shots << " (" << warmUpShots << " in the warm-up pass) |\n"
          << "| games | " << tally.games << " on " << levels.size() << " campaign level(s): " << tally.won << " won, "
          << tally.lost << " lost |\n"
          << "| simulated time | " << tally.simSeconds << " s |\n"
          << "| wall time | " << seconds << " s (" << 1000.0 * seconds / tally.shots << " ms per shot) |\n"
          << "| VmRSS before loading levels | " << megabytes(rssBeforeKb) << " |\n"
          << "| VmRSS at start (after one game per level) | " << megabytes(rssStartKb) << " |\n"
          << "| VmRSS at end | " << megabytes(rssEndKb) << " |\n"
          << "| growth start to end | " << std::setprecision(2) << 100.0 * growth << " % (limit " << 100.0 * kMaxGrowth
          << " %) |\n"
          << "| shots leaving a non-finite body state | " << tally.nonFinite << " |\n"
          << "| result | " << (pass ? "pass" : "FAIL: resident memory grew more than 5%") << " |\n";
    std::cout << "bench soak: " << tally.shots << " random shots (seed " << kSeed << ")\n" << table.str();

    const std::filesystem::path out(options.outDir);
    std::ofstream csv(out / "soak.csv");
    csv << "shots,wall_s,vmrss_kb\n";
    for (const auto& s : tally.samples)
        csv << s[0] << ',' << s[1] << ',' << s[2] << '\n';
    std::ofstream md(out / "soak.md");
    md << "# Soak: " << tally.shots << " headless shots across the campaign\n\n"
       << "Random angles (" << kMinAngleDeg << " to " << kMaxAngleDeg << " deg) and speeds (" << 100 * kMinSpeedShare
       << "% to 100% of each bird's maximum), seed " << kSeed << ". `abalike bench soak"
       << (options.quick ? " --quick" : "") << "`; VmRSS from /proc/self/status, sampled every " << kSampleEvery
       << " shots in soak.csv.\n\n"
       << table.str();
    if (!csv || !md)
    {
        std::cerr << "abalike: error: bench soak: cannot write soak.csv or soak.md in " << options.outDir << '\n';
        return 1;
    }
    return pass && tally.nonFinite == 0 ? 0 : 1;
}

} // namespace abalike::app
