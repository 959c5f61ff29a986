// `abalike bench generate`: how long a verified level takes, what is rejected on the way, and how varied the levels
// are (issue 40). Seeds 1..N, the loss share cycling through 0.1, 0.3, 0.5, 0.7 and 0.9. Each seed's result is kept
// in OUT/generate-seeds/ as it is made, and a run finds the seeds a stopped run already made there: the 200-level
// variety run (hours) can be run in parts.

#include "bench/BenchSuite.hpp"
#include "bench/ReportTable.hpp"
#include "shell/DataPaths.hpp"

#include <abalike/design/Generator.hpp>
#include <abalike/design/GeneratorLayouts.hpp>
#include <abalike/design/LayoutTwins.hpp>
#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/level/LevelWriter.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

namespace abalike::app
{

namespace
{

constexpr double kMedianTargetS = 120.0;
constexpr double kP95TargetS = 360.0;
constexpr double kToppleTarget = 0.4;
const double kLossShares[] = {0.1, 0.3, 0.5, 0.7, 0.9};

std::string fixedText(double value, int decimals)
{
    std::ostringstream text;
    text << std::fixed << std::setprecision(decimals) << value;
    return text.str();
}

/// Nearest-rank percentile.
double percentile(std::vector<double> values, double p)
{
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(values.size())));
    return values[std::clamp<std::size_t>(rank, 1, values.size()) - 1];
}

/// One seed's outcome, as kept on disk between runs.
struct SeedResult
{
    std::uint64_t seed = 0;
    double asked = 0.0;
    bool ok = false;
    std::string kind;
    LevelDef level;
    std::vector<ScriptedShot> shots; ///< the solver's win
    int attempts = 0;
    std::map<std::string, int> reasons;
    double lossShare = 0.0;
    double seconds = 0.0;
};

std::filesystem::path seedFile(const std::filesystem::path& folder, std::uint64_t seed, const char* suffix)
{
    return folder / (std::to_string(seed) + suffix);
}

void saveSeed(const std::filesystem::path& folder, const SeedResult& r)
{
    std::filesystem::create_directories(folder);
    nlohmann::json shots = nlohmann::json::array();
    for (const ScriptedShot& shot : r.shots)
        shots.push_back({{"angle_deg", shot.angleDeg},
                         {"speed", shot.speedMps},
                         {"ability_at_s", shot.abilityAtS ? nlohmann::json(*shot.abilityAtS) : nlohmann::json()}});
    const nlohmann::json row{
        {"seed", r.seed},      {"asked", r.asked},       {"ok", r.ok},           {"kind", r.kind},
        {"shots", shots},      {"attempts", r.attempts}, {"reasons", r.reasons}, {"loss_share", r.lossShare},
        {"seconds", r.seconds}};
    if (r.ok)
        std::ofstream(seedFile(folder, r.seed, ".level.json")) << writeLevelJson(r.level, "level.schema.json");
    // The row last: a run stopped between the two files makes this seed again.
    std::ofstream(seedFile(folder, r.seed, ".json")) << row.dump(1) << '\n';
}

/// A seed a stopped run made with the same loss share, if its files are whole.
std::optional<SeedResult> loadSeed(const std::filesystem::path& folder, std::uint64_t seed, double asked)
{
    try
    {
        std::ifstream in(seedFile(folder, seed, ".json"));
        if (!in)
            return std::nullopt;
        const nlohmann::json row = nlohmann::json::parse(in);
        SeedResult r;
        r.seed = seed;
        r.asked = row.at("asked").get<double>();
        if (r.asked != asked)
            return std::nullopt;
        r.ok = row.at("ok").get<bool>();
        r.kind = row.at("kind").get<std::string>();
        r.attempts = row.at("attempts").get<int>();
        r.reasons = row.at("reasons").get<std::map<std::string, int>>();
        r.lossShare = row.at("loss_share").get<double>();
        r.seconds = row.at("seconds").get<double>();
        for (const nlohmann::json& shot : row.at("shots"))
            r.shots.emplace_back(shot.at("angle_deg").get<double>(), shot.at("speed").get<double>(),
                                 shot.at("ability_at_s").is_null()
                                     ? std::nullopt
                                     : std::optional<double>(shot.at("ability_at_s").get<double>()));
        if (r.ok)
            r.level = loadLevel(seedFile(folder, seed, ".level.json").string(), Catalog::builtin());
        return r;
    }
    catch (const std::exception&)
    {
        return std::nullopt; // unreadable: made again
    }
}

SeedResult generateSeed(const std::vector<GeneratorPart>& parts, std::uint64_t seed, double asked)
{
    GeneratorOptions o;
    o.seed = seed;
    o.lossShare = asked;
    const GeneratedLevel g = generateLevel(parts, o, Catalog::builtin());
    SeedResult r;
    r.seed = seed;
    r.asked = asked;
    r.ok = g.ok;
    r.kind = g.ok ? generatedKindName(g.kind) : "";
    r.level = g.level;
    r.shots = g.solution.shots;
    r.attempts = g.attempts;
    for (const Rejection rejection : g.rejected)
        ++r.reasons[rejectionName(rejection)];
    r.lossShare = g.lossShare;
    r.seconds = g.seconds;
    return r;
}

} // namespace

int runGenerateBench(const BenchOptions& options)
{
    const std::size_t seeds = options.seeds > 0 ? options.seeds : (options.quick ? 2 : 20);
    const std::vector<GeneratorPart> parts =
        loadGeneratorParts((std::filesystem::path(levelsDirectory()) / "parts").string(), Catalog::builtin());
    ReportTable rows({"seed", "loss_share_asked", "ok", "kind", "bodies", "birds", "loss_share", "attempts", "fell",
                      "unwinnable", "too_easy", "too_hard", "seconds"});
    std::vector<double> seconds;
    std::map<std::string, int> rejected;
    std::map<std::string, int> kinds;
    std::vector<LevelDef> made;
    int pigs = 0;
    int toppled = 0;
    int failed = 0;
    const std::filesystem::path kept = std::filesystem::path(options.outDir) / "generate-seeds";
    int reused = 0;
    for (std::size_t i = 0; i < seeds; ++i)
    {
        const std::uint64_t seed = i + 1;
        const double asked = kLossShares[i % 5];
        std::optional<SeedResult> r = loadSeed(kept, seed, asked);
        if (r)
            ++reused;
        else
        {
            r = generateSeed(parts, seed, asked);
            saveSeed(kept, *r);
        }
        for (const auto& [reason, count] : r->reasons)
            rejected[reason] += count;
        seconds.push_back(r->seconds);
        const auto count = [&r](const char* reason)
        {
            const auto found = r->reasons.find(reason);
            return std::to_string(found == r->reasons.end() ? 0 : found->second);
        };
        rows.addRow({std::to_string(seed), fixedText(asked, 1), r->ok ? "1" : "0", r->kind,
                     std::to_string(r->level.blocks.size() + r->level.pigs.size()),
                     std::to_string(r->level.birds.size()), fixedText(r->lossShare, 3), std::to_string(r->attempts),
                     count("fell"), count("unwinnable"), count("too easy"), count("too hard"),
                     fixedText(r->seconds, 1)});
        std::cerr << "seed " << seed << ": " << (r->ok ? r->kind : "none") << ", " << fixedText(r->seconds, 1)
                  << " s\n";
        if (!r->ok)
        {
            ++failed;
            continue;
        }
        ++kinds[r->kind];
        made.push_back(r->level);
        // Toppling over the solver's winning shots: pigs defeated by a block, another pig or the ground.
        const auto session = simulateShots(r->level, r->shots);
        for (const DestroyedEvent& defeat : session->defeats())
            if (defeat.kind == EntityKind::Pig)
            {
                ++pigs;
                toppled += defeat.cause.kind == CauseKind::Block || defeat.cause.kind == CauseKind::Pig ||
                                   defeat.cause.kind == CauseKind::Ground
                               ? 1
                               : 0;
            }
    }
    double closest = 1.0;
    std::string closestPair = "-";
    std::size_t twins = 0;
    double mostAlike = 0.0;
    std::string mostAlikePair = "-";
    for (std::size_t a = 0; a < made.size(); ++a)
        for (std::size_t b = a + 1; b < made.size(); ++b)
        {
            const double d = layoutDistance(made[a], made[b], Catalog::builtin());
            if (d < closest)
            {
                closest = d;
                closestPair = made[a].id + " and " + made[b].id;
            }
            const double share = layoutTwinShare(made[a], made[b]);
            twins += share >= kTwinShare ? 1 : 0;
            if (share > mostAlike)
            {
                mostAlike = share;
                mostAlikePair = made[a].id + " and " + made[b].id;
            }
        }

    const double median = percentile(seconds, 0.5);
    const double p95 = percentile(seconds, 0.95);
    const double toppleShare = pigs > 0 ? static_cast<double>(toppled) / pigs : 0.0;
    std::ostringstream md;
    md << "# bench generate\n\n"
       << seeds << " seeds (1 to " << seeds << "), loss share 0.1, 0.3, 0.5, 0.7, 0.9 in turn, 40 model-player runs "
       << "per measure, every core; " << reused << " of them made by an earlier run into this folder (times are "
       << "that run's). " << loadAverageNote() << "\n\n"
       << "| measure | value | target |\n|---|---:|---|\n"
       << "| levels generated | " << made.size() << " of " << seeds << " | all |\n"
       << "| time per verified level: median | " << fixedText(median, 1) << " s | <= " << kMedianTargetS << " s |\n"
       << "| ... 95th percentile | " << fixedText(p95, 1) << " s | <= " << kP95TargetS << " s |\n"
       << "| ... max | " << fixedText(seconds.empty() ? 0.0 : *std::max_element(seconds.begin(), seconds.end()), 1)
       << " s | |\n";
    for (const char* reason : {"fell", "unwinnable", "too easy", "too hard"})
        md << "| attempts rejected: " << reason << " | " << rejected[reason] << " | |\n";
    md << "| kinds | " << kinds.size() << " of " << generatedKinds().size() << " | every kind (over 200 levels) |\n"
       << "| closest two layouts (occupancy-grid distance) | " << fixedText(closest, 3) << " (" << closestPair
       << ") | |\n"
       << "| layout twins (>= " << fixedText(100 * kTwinShare, 0) << " % of the bodies of each paired within "
       << fixedText(kTwinSidewaysM, 1) << " m sideways, " << fixedText(kTwinVerticalM, 1) << " m up or down) | "
       << twins << " (most alike: " << mostAlikePair << ", " << fixedText(100 * mostAlike, 0)
       << " %) | 0: no two alike |\n"
       << "| pigs defeated by toppling over the solver's wins | " << toppled << " of " << pigs << " ("
       << fixedText(100.0 * toppleShare, 0) << " %) | >= " << fixedText(100 * kToppleTarget, 0) << " % |\n\n"
       << "Kinds: ";
    for (const auto& [kind, count] : kinds)
        md << kind << " " << count << "; ";
    md << "\n\n" << rows.markdown();
    std::ofstream(std::filesystem::path(options.outDir) / "generate.md") << md.str();
    std::ofstream(std::filesystem::path(options.outDir) / "generate.csv") << rows.csv();
    std::cout << md.str();
    return failed == 0 ? 0 : 1;
}

} // namespace abalike::app
