// `abalike bench feel`: does the game play like the genre? Break-through, toppling and the pace of turns, measured
// over the campaign (issue 19). Targets are reported against the measurement, never asserted.
#include "bench/BenchSuite.hpp"
#include "bench/ReportTable.hpp"
#include "shell/DataPaths.hpp"

#include <abalike/design/Solver.hpp>
#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace abalike::app
{

namespace
{

/// Targets of issue 19.
constexpr double kKeepSignTarget = 0.90;
constexpr double kReverseTarget = 0.10;
constexpr double kMedianTurnTargetS = 2.5;
constexpr double kMaxTurnTargetS = 3.1;
/// Target of issue 22: the share of pigs defeated by toppling, in every episode.
constexpr double kToppleShareTarget = 0.4;

/// One shot of the grid: the first bird of a level, from the level's start.
struct GridShot
{
    std::string level;
    double angleDeg = 0.0;
    double share = 0.0; ///< of the first bird's fastest launch
    double speedMps = 0.0;
    std::string firstTouched; ///< ground, terrain, block, pig, bird or none
    std::string material;     ///< of the block it first touched
    bool broke = false;       ///< the first contact's impulse reached the body's remaining strength
    double vxBefore = 0.0;    ///< the bird's horizontal velocity before and after the contact step
    double vxAfter = 0.0;
    bool won = false;
    double turnS = 0.0;                       ///< launch until the next bird is ready or the level ends
    std::optional<double> readyAfterContactS; ///< first contact until then
};

const char* kindName(std::optional<EntityKind> kind)
{
    return kind ? entityKindName(*kind) : "none";
}

/// One grid shot under either rule: break-through (now) or the solver's impulse as solved (before).
GridShot playGridShot(const LevelDef& level, double angleDeg, double share, bool breakThrough)
{
    WorldSettings settings;
    settings.breakThrough = breakThrough;
    GameSession session(level, Catalog::builtin(), settings);
    GridShot row;
    row.level = level.id;
    row.angleDeg = angleDeg;
    row.share = share;
    row.speedMps = share * session.maxLaunchSpeed();
    const double launchedAt = session.simTime();
    session.launch(angleDeg, row.speedMps);
    while (session.phase() == Phase::Flying)
        session.step();
    const ShotRecord& shot = session.shots().front();
    row.firstTouched = kindName(shot.firstTouched);
    if (shot.impact)
    {
        row.material = shot.impact->bodyType;
        row.broke = shot.impact->broke;
        row.vxBefore = shot.impact->birdBefore.vx;
        row.vxAfter = shot.impact->birdAfter.vx;
    }
    row.won = session.phase() == Phase::Won;
    row.turnS = session.simTime() - launchedAt;
    row.readyAfterContactS = shot.readyAfterContactS;
    return row;
}

/// Per material (wood, ice): grid shots whose first contact broke the block, and of those how many kept the sign
/// of the bird's horizontal velocity and how many reversed it.
std::map<std::string, std::array<int, 3>> breakThroughCounts(const std::vector<GridShot>& grid)
{
    std::map<std::string, std::array<int, 3>> counts;
    for (const GridShot& g : grid)
        if (g.firstTouched == "block" && g.broke && (g.material == "wood" || g.material == "ice"))
        {
            auto& c = counts[g.material];
            ++c[0];
            c[1] += g.vxBefore * g.vxAfter > 0.0 ? 1 : 0;
            c[2] += g.vxBefore * g.vxAfter < 0.0 ? 1 : 0;
        }
    return counts;
}

/// Pig defeats by cause over the solver's winning shot sequences of the levels.
struct CauseTally
{
    std::map<std::string, int> pigsByCause;
    std::map<std::string, std::map<std::string, int>> pigsByEpisode; ///< episode id -> cause -> pigs
    int levelsWon = 0;
    int levelsSolved = 0;
};

int countOf(const std::map<std::string, int>& byCause, const char* cause)
{
    const auto it = byCause.find(cause);
    return it == byCause.end() ? 0 : it->second;
}

int toppledPigs(const std::map<std::string, int>& byCause)
{
    return countOf(byCause, "block") + countOf(byCause, "pig") + countOf(byCause, "ground");
}

int allPigs(const std::map<std::string, int>& byCause)
{
    int pigs = 0;
    for (const auto& [cause, count] : byCause)
        pigs += count;
    return pigs;
}

CauseTally tallyWinningShots(const std::vector<LevelDef>& levels)
{
    CauseTally tally;
    for (const LevelDef& level : levels)
    {
        ++tally.levelsSolved;
        const Solution solution = solveLevel(level);
        if (!solution.outcome.won)
            continue;
        ++tally.levelsWon;
        const auto session = simulateShots(level, solution.shots);
        for (const DestroyedEvent& defeat : session->defeats())
            if (defeat.kind == EntityKind::Pig)
            {
                ++tally.pigsByCause[causeKindName(defeat.cause.kind)];
                ++tally.pigsByEpisode[level.episode][causeKindName(defeat.cause.kind)];
            }
    }
    return tally;
}

double interpolatedPercentile(std::vector<double> values, double p)
{
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    const double rank = p * static_cast<double>(values.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(rank));
    const auto hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (rank - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

std::string fixed(double value, int decimals)
{
    std::ostringstream text;
    text << std::fixed << std::setprecision(decimals) << value;
    return text.str();
}

std::string share(int part, int whole)
{
    return std::to_string(part) + " of " + std::to_string(whole) +
           (whole > 0 ? " (" + fixed(100.0 * part / whole, 0) + " %)" : "");
}

std::string verdict(bool met)
{
    return met ? "met" : "missed";
}

} // namespace

int runFeelBench(const BenchOptions& options)
{
    std::vector<LevelDef> levels;
    for (const std::string& path : loadCampaign(campaignManifest()))
        levels.push_back(loadLevel(path, Catalog::builtin()));
    if (options.quick)
        levels.resize(std::min<std::size_t>(levels.size(), 3));
    const auto start = std::chrono::steady_clock::now();

    // The grid: every level's first bird at 0-60 degrees in 6 degree steps, at 60, 80 and 100 % of its fastest launch.
    std::vector<GridShot> grid;
    std::vector<GridShot> before; // the same grid without break-through
    for (const LevelDef& level : levels)
        for (int angle = 0; angle <= 60; angle += 6)
            for (const double s : {0.6, 0.8, 1.0})
            {
                grid.push_back(playGridShot(level, angle, s, true));
                before.push_back(playGridShot(level, angle, s, false));
            }

    ReportTable shots({"level", "angle_deg", "share", "speed_mps", "first_touched", "material", "broke",
                       "vx_before_mps", "vx_after_mps", "won", "turn_s", "ready_after_contact_s"});
    std::map<std::string, std::array<int, 3>> byMaterial; // broke: total, keeps sign, reverses
    const std::map<std::string, std::array<int, 3>> byMaterialBefore = breakThroughCounts(before);
    std::vector<double> turns;
    std::vector<double> readyAfterContact;
    for (const GridShot& g : grid)
    {
        shots.addRow({g.level, fixed(g.angleDeg, 0), fixed(g.share, 1), fixed(g.speedMps, 3), g.firstTouched,
                      g.material, g.broke ? "1" : "0", fixed(g.vxBefore, 4), fixed(g.vxAfter, 4), g.won ? "1" : "0",
                      fixed(g.turnS, 3), g.readyAfterContactS ? fixed(*g.readyAfterContactS, 3) : ""});
        if (!g.won)
        {
            turns.push_back(g.turnS);
            if (g.readyAfterContactS)
                readyAfterContact.push_back(*g.readyAfterContactS);
        }
    }
    byMaterial = breakThroughCounts(grid);
    int broke = 0;
    int keeps = 0;
    int reverses = 0;
    for (const auto& [material, counts] : byMaterial)
    {
        broke += counts[0];
        keeps += counts[1];
        reverses += counts[2];
    }
    const int blockFirst = static_cast<int>(
        std::count_if(grid.begin(), grid.end(), [](const GridShot& g) { return g.firstTouched == "block"; }));

    std::ostringstream md;
    md << "# bench feel\n\n"
       << "Campaign levels: " << levels.size() << "; grid: the first bird at 0-60 deg in 6 deg steps at 60, 80 and "
       << "100 % of its fastest launch, " << grid.size() << " shots, " << blockFirst
       << " of them first touched a block. " << loadAverageNote() << "\n\n"
       << "## Break-through\n\nFirst contacts with a wood or ice block whose impulse reached the block's remaining "
          "strength (it broke in that step), and what the bird's horizontal velocity did across that step:\n\n"
       << "| material | rule | broke on first contact | bird keeps moving forward | bird bounces back "
          "|\n|---|---|---:|---:|---:|\n";
    for (const auto& [material, counts] : byMaterialBefore)
        md << "| " << material << " | before (the solver's impulse stands) | " << counts[0] << " | "
           << share(counts[1], counts[0]) << " | " << share(counts[2], counts[0]) << " |\n";
    for (const auto& [material, counts] : byMaterial)
        md << "| " << material << " | break-through | " << counts[0] << " | " << share(counts[1], counts[0]) << " | "
           << share(counts[2], counts[0]) << " |\n";
    const double keepShare = broke > 0 ? static_cast<double>(keeps) / broke : 0.0;
    const double reverseShare = broke > 0 ? static_cast<double>(reverses) / broke : 0.0;
    md << "| all | break-through | " << broke << " | " << share(keeps, broke) << " | " << share(reverses, broke)
       << " |\n\n"
       << "Targets: keeps its sign >= " << fixed(100 * kKeepSignTarget, 0) << " %: **"
       << verdict(keepShare >= kKeepSignTarget) << "**; reverses <= " << fixed(100 * kReverseTarget, 0) << " %: **"
       << verdict(reverseShare <= kReverseTarget) << "**.\n\n";

    const double median = interpolatedPercentile(turns, 0.5);
    const double p90 = interpolatedPercentile(turns, 0.9);
    const double worst = turns.empty() ? 0.0 : *std::max_element(turns.begin(), turns.end());
    const double readyMedian = interpolatedPercentile(readyAfterContact, 0.5);
    const double readyP90 = interpolatedPercentile(readyAfterContact, 0.9);
    const double readyMax =
        readyAfterContact.empty() ? 0.0 : *std::max_element(readyAfterContact.begin(), readyAfterContact.end());
    md << "## Pace of turns\n\nShots of the grid that did not win (" << turns.size()
       << "), in seconds of game time:\n\n"
       << "| | median | 90th percentile | max |\n|---|---:|---:|---:|\n"
       << "| launch until the next bird is ready or the level ends | " << fixed(median, 2) << " | " << fixed(p90, 2)
       << " | " << fixed(worst, 2) << " |\n"
       << "| first contact until then (`ready_after_contact_s`) | " << fixed(readyMedian, 2) << " | "
       << fixed(readyP90, 2) << " | " << fixed(readyMax, 2) << " |\n\n"
       << "Targets (first contact until ready): median <= " << fixed(kMedianTurnTargetS, 1) << " s: **"
       << verdict(readyMedian <= kMedianTurnTargetS) << "**; max <= " << fixed(kMaxTurnTargetS, 1) << " s: **"
       << verdict(readyMax <= kMaxTurnTargetS) << "**.\n";

    const CauseTally tally = tallyWinningShots(levels);
    const int pigs = allPigs(tally.pigsByCause);
    const auto count = [&](const char* cause)
    {
        return countOf(tally.pigsByCause, cause);
    };
    md << "\n## What defeats the pigs\n\nThe solver's best shot sequence for each level (" << tally.levelsWon << " of "
       << tally.levelsSolved << " levels won), replayed; each pig's cause is the body that delivered the "
       << "largest impulse in the step its health ran out:\n\n| cause | pigs |\n|---|---:|\n";
    for (const char* cause : {"bird", "block", "pig", "ground", "explosion", "egg", "out_of_bounds"})
        md << "| " << cause << " | " << share(count(cause), pigs) << " |\n";
    md << "| toppling (block, pig, ground) | " << share(toppledPigs(tally.pigsByCause), pigs) << " |\n";

    // Per episode: toppling against every defeat (explosions and eggs are in the total, not in toppling).
    md << "\nBy episode (target: toppling >= " << fixed(100.0 * kToppleShareTarget, 0)
       << " % of the pigs defeated in every episode):\n\n"
       << "| episode | pigs | bird | toppling | explosion | egg | toppling share | target |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---|\n";
    for (const auto& [episode, byCause] : tally.pigsByEpisode)
    {
        const int total = allPigs(byCause);
        const int toppled = toppledPigs(byCause);
        const double toppledShare = total > 0 ? static_cast<double>(toppled) / total : 0.0;
        md << "| " << (episode.empty() ? "-" : episode) << " | " << total << " | " << countOf(byCause, "bird") << " | "
           << toppled << " | " << countOf(byCause, "explosion") << " | " << countOf(byCause, "egg") << " | "
           << fixed(100.0 * toppledShare, 0) << " % | " << verdict(toppledShare >= kToppleShareTarget) << " |\n";
    }

    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    md << "\nWall time " << fixed(seconds, 1) << " s.\n";
    std::cout << md.str();
    const bool written = writeReportFile(options.outDir, "feel.md", md.str()) &&
                         writeReportFile(options.outDir, "feel.csv", shots.csv());
    return written ? 0 : 1;
}

} // namespace abalike::app
