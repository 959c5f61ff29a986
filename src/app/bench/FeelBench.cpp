// `abalike bench feel`: does the game play like the genre? The birds' roles, break-through, toppling and the pace of
// turns, measured over the campaign against the rules before (issues 19 and 37). Targets are reported against the
// measurement, never asserted.
#include "bench/BenchSuite.hpp"
#include "bench/BirdRoles.hpp"
#include "bench/HitTable.hpp"
#include "bench/ReportTable.hpp"
#include "bench/TowerTable.hpp"
#include "render/TextFormat.hpp"
#include "shell/DataPaths.hpp"

#include <abalike/design/Solver.hpp>
#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <algorithm>
#include <box2d/box2d.h>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
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
/// Target of issue 37: each bird breaks the material it is for in this share of its full-pull direct hits.
constexpr double kRoleTarget = 0.8;

/// A break of a wood or ice block by the launched bird, at any contact of its shot: its horizontal velocity across
/// the step in which the block broke.
struct BirdBreak
{
    std::string material;
    double vxBefore = 0.0;
    double vxAfter = 0.0;
};

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
    std::vector<BirdBreak> breaks;            ///< every wood or ice block the bird broke, at any contact
};

/// The rules of the game: this round's, or the rules before it (the black bird's blast at 250 N s, a breaking block's
/// momentum leaving with it, and a breaking block springing back at what struck it with Box2D's restitution and whole
/// friction).
struct Rules
{
    WorldSettings settings;
    Catalog catalog = Catalog::builtin();
};

Rules rulesBefore()
{
    Rules rules;
    rules.settings.handOnMomentum = false;
    rules.settings.breakingBodyYields = false;
    nlohmann::json text = nlohmann::json::parse(Catalog::builtinJson());
    text["abilities"]["explode"]["impulse_ns"] = 250.0;
    rules.catalog = Catalog::fromJson(text.dump());
    return rules;
}

const char* kindName(std::optional<EntityKind> kind)
{
    return kind ? entityKindName(*kind) : "none";
}

/// Wood or ice: what a bird should break through and fly on.
bool brittle(const Catalog& catalog, const std::string& material)
{
    const Material* found = catalog.findMaterial(material);
    return found != nullptr && (found->look.surface == SurfaceKind::Grain || found->look.surface == SurfaceKind::Frost);
}

/// One grid shot under the given rules.
GridShot playGridShot(const LevelDef& level, double angleDeg, double share, const Rules& rules)
{
    GameSession session(level, rules.catalog, rules.settings);
    GridShot row;
    row.level = level.id;
    row.angleDeg = angleDeg;
    row.share = share;
    row.speedMps = share * session.maxLaunchSpeed();
    const double launchedAt = session.simTime();
    session.launch(angleDeg, row.speedMps);
    std::size_t seen = 0;
    while (session.phase() == Phase::Flying)
    {
        const Entity* bird = session.world().bird();
        const bool flying = bird != nullptr && bird->body != nullptr;
        const double vxBefore = flying ? bird->body->GetLinearVelocity().x : 0.0;
        session.step();
        const std::vector<DestroyedEvent>& destroyed = session.destroyed();
        for (; seen < destroyed.size(); ++seen)
        {
            const DestroyedEvent& event = destroyed[seen];
            const Entity* after = session.world().bird();
            if (event.kind == EntityKind::Block && event.cause.kind == CauseKind::Bird && flying && after != nullptr &&
                after->body != nullptr && brittle(rules.catalog, event.typeName))
                row.breaks.push_back({event.typeName, vxBefore, after->body->GetLinearVelocity().x});
        }
    }
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

/// Per material (wood, ice): the first contacts that broke a block, and of those how many kept the sign of the bird's
/// horizontal velocity and how many reversed it.
std::map<std::string, std::array<int, 3>> breakThroughCounts(const std::vector<GridShot>& grid, const Catalog& catalog)
{
    std::map<std::string, std::array<int, 3>> counts;
    for (const GridShot& g : grid)
        if (g.firstTouched == "block" && g.broke && brittle(catalog, g.material))
        {
            auto& c = counts[g.material];
            ++c[0];
            c[1] += g.vxBefore * g.vxAfter > 0.0 ? 1 : 0;
            c[2] += g.vxBefore * g.vxAfter < 0.0 ? 1 : 0;
        }
    return counts;
}

/// Below this sideways speed a bird has no direction to keep that a player could see (a roll, a bird pinned in a
/// collapse): the any-contact table also shows the breaks on either side of it.
constexpr double kSidewaysMps = 1.0;

/// The same over every wood or ice block the bird broke, at any contact of its shot, of the breaks where the bird
/// moved sideways at least minMps and below maxMps before it.
std::array<int, 3> allBreakCounts(const std::vector<GridShot>& grid, double minMps = 0.0,
                                  double maxMps = std::numeric_limits<double>::infinity())
{
    std::array<int, 3> counts{};
    for (const GridShot& g : grid)
        for (const BirdBreak& b : g.breaks)
        {
            if (std::abs(b.vxBefore) < minMps || std::abs(b.vxBefore) >= maxMps)
                continue;
            ++counts[0];
            counts[1] += b.vxBefore * b.vxAfter > 0.0 ? 1 : 0;
            counts[2] += b.vxBefore * b.vxAfter < 0.0 ? 1 : 0;
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
                ++tally.pigsByCause[causeName(defeat.cause)];
                ++tally.pigsByEpisode[level.episode][causeName(defeat.cause)];
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

std::string share(int part, int whole)
{
    return std::to_string(part) + " of " + std::to_string(whole) +
           (whole > 0 ? " (" + formatFixed(100.0 * part / whole, 0) + " %)" : "");
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
    const Rules now;
    const Rules earlier = rulesBefore();
    std::vector<GridShot> grid;
    std::vector<GridShot> before; // the same grid under the rules before
    for (const LevelDef& level : levels)
        for (int angle = 0; angle <= 60; angle += 6)
            for (const double s : {0.6, 0.8, 1.0})
            {
                grid.push_back(playGridShot(level, angle, s, now));
                before.push_back(playGridShot(level, angle, s, earlier));
            }

    ReportTable shots({"level", "angle_deg", "share", "speed_mps", "first_touched", "material", "broke",
                       "vx_before_mps", "vx_after_mps", "won", "turn_s", "ready_after_contact_s"});
    std::map<std::string, std::array<int, 3>> byMaterial; // broke: total, keeps sign, reverses
    const std::map<std::string, std::array<int, 3>> byMaterialBefore = breakThroughCounts(before, earlier.catalog);
    std::vector<double> turns;
    std::vector<double> readyAfterContact;
    for (const GridShot& g : grid)
    {
        shots.addRow({g.level, formatFixed(g.angleDeg, 0), formatFixed(g.share, 1), formatFixed(g.speedMps, 3),
                      g.firstTouched, g.material, g.broke ? "1" : "0", formatFixed(g.vxBefore, 4),
                      formatFixed(g.vxAfter, 4), g.won ? "1" : "0", formatFixed(g.turnS, 3),
                      g.readyAfterContactS ? formatFixed(*g.readyAfterContactS, 3) : ""});
        if (!g.won)
        {
            turns.push_back(g.turnS);
            if (g.readyAfterContactS)
                readyAfterContact.push_back(*g.readyAfterContactS);
        }
    }
    byMaterial = breakThroughCounts(grid, now.catalog);
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
       << " of them first touched a block. Before: the rules before issue 37 (the black bird's blast 250 N s, a "
          "breaking block's momentum leaving with it, and springing back at what struck it), in the same run. "
       << loadAverageNote() << "\n\n";

    // The birds' roles: each bird against each material at full pull, over a fan of aims that hit a lone block.
    md << "## Birds and their materials\n\nFull-pull shots at a lone 1 m block on flat ground 10 m away, aims from "
          "-5 to 45 deg in 0.5 deg steps; of the aims whose first contact is the block, the share that broke it. "
          "Each bird's own material and use is marked; the target is >= "
       << formatFixed(100 * kRoleTarget, 0) << " % there.\n\n"
       << "| bird | use | wood | ice | stone | its role | target |\n|---|---|---:|---:|---:|---|---|\n";
    struct Role
    {
        const char* bird;
        RoleUse use;
        const char* material; ///< the one it is for; empty: none
    };
    for (const Role& role : {Role{"red", RoleUse::DirectHit, ""}, Role{"blue", RoleUse::DirectHit, "ice"},
                             Role{"blue", RoleUse::AbilityEarly, "ice"}, Role{"yellow", RoleUse::DirectHit, ""},
                             Role{"yellow", RoleUse::AbilityEarly, "wood"}, Role{"black", RoleUse::DirectHit, ""},
                             Role{"black", RoleUse::AbilityAtContact, "stone"}, Role{"white", RoleUse::DirectHit, ""}})
    {
        md << "| " << role.bird << " | " << roleUseName(role.use) << " |";
        std::string verdictText = "-";
        for (const char* material : {"wood", "ice", "stone"})
        {
            const RoleRow row = measureRole(role.bird, material, role.use);
            md << " " << share(row.broke, row.directHits) << " |";
            if (std::string(material) == role.material)
                verdictText = verdict(row.directHits > 0 && row.broke >= kRoleTarget * row.directHits);
        }
        md << " " << (*role.material != '\0' ? role.material : "-") << " | " << verdictText << " |\n";
    }

    const HitTable hits = measureHits(levels, options.quick ? 20 : 2);
    md << "\n## Hits\n\nEvery campaign level" << (options.quick ? " (--quick: 3 levels, 20 deg steps)" : "")
       << ", the launch at 0-60 deg in 2 deg steps and 70, 85 and 100 % pull, each bird the level has as its first "
          "bird: a strike is the bird's first contact when it is a block, a break that block destroyed within 0.5 s. "
       << hits.shots << " shots. Targets of issue 57 (red into stone is a counter-target: nothing simply softened).\n\n"
       << hitTableMarkdown(hits);

    const TowerTable towers = measureTowers(levels, options.quick ? 20 : 2);
    md << "\n## Towers\n\nThe same levels and launches, the level's first bird, each shot played until the next bird "
          "is ready: a shot brings a tower down when a block that stood at least 2 m above its tower's base (blocks "
          "touching when the level starts) falls at least 1 m; the pigs within 1 m of that tower's footprint and below "
          "its top are under or beside it. Target of issue 57: at least 70 % of them defeated.\n\n"
       << towerTableMarkdown(towers);

    md << "\n## Break-through\n\nFirst contacts with a wood or ice block whose impulse reached the block's remaining "
          "strength (it broke in that step), and what the bird's horizontal velocity did across that step:\n\n"
       << "| material | rules | broke on first contact | bird keeps moving forward | bird bounces back "
          "|\n|---|---|---:|---:|---:|\n";
    for (const auto& [material, counts] : byMaterialBefore)
        md << "| " << material << " | before | " << counts[0] << " | " << share(counts[1], counts[0]) << " | "
           << share(counts[2], counts[0]) << " |\n";
    for (const auto& [material, counts] : byMaterial)
        md << "| " << material << " | now | " << counts[0] << " | " << share(counts[1], counts[0]) << " | "
           << share(counts[2], counts[0]) << " |\n";
    const double keepShare = broke > 0 ? static_cast<double>(keeps) / broke : 0.0;
    const double reverseShare = broke > 0 ? static_cast<double>(reverses) / broke : 0.0;
    md << "| all | now | " << broke << " | " << share(keeps, broke) << " | " << share(reverses, broke) << " |\n\n";
    // Every wood or ice block the bird broke, at any contact of the shot, not only the first.
    const std::array<int, 3> allBefore = allBreakCounts(before);
    const std::array<int, 3> all = allBreakCounts(grid);
    const std::array<int, 3> fast = allBreakCounts(grid, kSidewaysMps);
    const std::array<int, 3> slow = allBreakCounts(grid, 0.0, kSidewaysMps);
    const double allKeepShare = all[0] > 0 ? static_cast<double>(all[1]) / all[0] : 0.0;
    md << "Every wood or ice block the bird broke at any contact of its shot:\n\n"
       << "| rules | breaks | bird keeps moving forward | bird bounces back |\n|---|---:|---:|---:|\n"
       << "| before | " << allBefore[0] << " | " << share(allBefore[1], allBefore[0]) << " | "
       << share(allBefore[2], allBefore[0]) << " |\n"
       << "| now | " << all[0] << " | " << share(all[1], all[0]) << " | " << share(all[2], all[0]) << " |\n"
       << "| now, the bird moving sideways at >= " << formatFixed(kSidewaysMps, 0) << " m/s before | " << fast[0]
       << " | " << share(fast[1], fast[0]) << " | " << share(fast[2], fast[0]) << " |\n"
       << "| now, the bird slower sideways (rolling, pinned) | " << slow[0] << " | " << share(slow[1], slow[0]) << " | "
       << share(slow[2], slow[0]) << " |\n\n"
       << "Targets: on first contact keeps its sign >= " << formatFixed(100 * kKeepSignTarget, 0) << " %: **"
       << verdict(keepShare >= kKeepSignTarget) << "**; reverses <= " << formatFixed(100 * kReverseTarget, 0)
       << " %: **" << verdict(reverseShare <= kReverseTarget)
       << "**; at any contact keeps its sign >= " << formatFixed(100 * kKeepSignTarget, 0) << " %: **"
       << verdict(allKeepShare >= kKeepSignTarget) << "**.\n\n";

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
       << "| launch until the next bird is ready or the level ends | " << formatFixed(median, 2) << " | "
       << formatFixed(p90, 2) << " | " << formatFixed(worst, 2) << " |\n"
       << "| first contact until then (`ready_after_contact_s`) | " << formatFixed(readyMedian, 2) << " | "
       << formatFixed(readyP90, 2) << " | " << formatFixed(readyMax, 2) << " |\n\n"
       << "Targets (first contact until ready): median <= " << formatFixed(kMedianTurnTargetS, 1) << " s: **"
       << verdict(readyMedian <= kMedianTurnTargetS) << "**; max <= " << formatFixed(kMaxTurnTargetS, 1) << " s: **"
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
    // The kinds of cause, with each ability that drops a payload in place of the kind "ability" (the egg).
    std::vector<std::string> dropping;
    for (const auto& ability : Catalog::builtin().abilities())
        if (ability->dropped())
            dropping.emplace_back(ability->name());
    std::vector<std::string> causes{"bird", "block", "pig", "ground", "explosion"};
    causes.insert(causes.end(), dropping.begin(), dropping.end());
    causes.emplace_back("out_of_bounds");
    for (const std::string& cause : causes)
        md << "| " << cause << " | " << share(count(cause.c_str()), pigs) << " |\n";
    md << "| toppling (block, pig, ground) | " << share(toppledPigs(tally.pigsByCause), pigs) << " |\n";

    // Per episode: toppling against every defeat (explosions and eggs are in the total, not in toppling).
    md << "\nBy episode (target: toppling >= " << formatFixed(100.0 * kToppleShareTarget, 0)
       << " % of the pigs defeated in every episode):\n\n"
       << "| episode | pigs | bird | toppling | explosion | ";
    for (const std::string& name : dropping)
        md << name << " | ";
    md << "toppling share | target |\n|---|---:|---:|---:|---:|";
    for (std::size_t i = 0; i < dropping.size(); ++i)
        md << "---:|";
    md << "---:|---|\n";
    for (const auto& [episode, byCause] : tally.pigsByEpisode)
    {
        const int total = allPigs(byCause);
        const int toppled = toppledPigs(byCause);
        const double toppledShare = total > 0 ? static_cast<double>(toppled) / total : 0.0;
        md << "| " << (episode.empty() ? "-" : episode) << " | " << total << " | " << countOf(byCause, "bird") << " | "
           << toppled << " | " << countOf(byCause, "explosion") << " | ";
        for (const std::string& name : dropping)
            md << countOf(byCause, name.c_str()) << " | ";
        md << formatFixed(100.0 * toppledShare, 0) << " % | " << verdict(toppledShare >= kToppleShareTarget) << " |\n";
    }

    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    md << "\nWall time " << formatFixed(seconds, 1) << " s.\n";
    std::cout << md.str();
    const bool written = writeReportFile(options.outDir, "feel.md", md.str()) &&
                         writeReportFile(options.outDir, "feel.csv", shots.csv());
    return written ? 0 : 1;
}

} // namespace abalike::app
