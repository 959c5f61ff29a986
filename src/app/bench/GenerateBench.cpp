// `abalike bench generate`: how long a verified level takes, what is rejected on the way, and how varied the levels
// are (issue 40). Seeds 1..N, the loss share cycling through 0.1, 0.3, 0.5, 0.7 and 0.9.

#include "bench/BenchSuite.hpp"
#include "bench/ReportTable.hpp"
#include "shell/DataPaths.hpp"

#include <abalike/design/Generator.hpp>
#include <abalike/design/GeneratorLayouts.hpp>
#include <abalike/game/GameSession.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
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
    for (std::size_t i = 0; i < seeds; ++i)
    {
        GeneratorOptions o;
        o.seed = i + 1;
        o.lossShare = kLossShares[i % 5];
        const GeneratedLevel g = generateLevel(parts, o, Catalog::builtin());
        std::map<std::string, int> reasons;
        for (const Rejection r : g.rejected)
        {
            ++reasons[rejectionName(r)];
            ++rejected[rejectionName(r)];
        }
        seconds.push_back(g.seconds);
        rows.addRow({std::to_string(o.seed), fixedText(o.lossShare, 1), g.ok ? "1" : "0",
                     g.ok ? generatedKindName(g.kind) : "", std::to_string(g.level.blocks.size() + g.level.pigs.size()),
                     std::to_string(g.level.birds.size()), fixedText(g.lossShare, 3), std::to_string(g.attempts),
                     std::to_string(reasons["fell"]), std::to_string(reasons["unwinnable"]),
                     std::to_string(reasons["too easy"]), std::to_string(reasons["too hard"]),
                     fixedText(g.seconds, 1)});
        std::cerr << "seed " << o.seed << ": " << (g.ok ? generatedKindName(g.kind) : "none") << ", "
                  << fixedText(g.seconds, 1) << " s\n";
        if (!g.ok)
        {
            ++failed;
            continue;
        }
        ++kinds[generatedKindName(g.kind)];
        made.push_back(g.level);
        // Toppling over the solver's winning shots: pigs defeated by a block, another pig or the ground.
        const auto session = simulateShots(g.level, g.solution.shots);
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
    for (std::size_t a = 0; a < made.size(); ++a)
        for (std::size_t b = a + 1; b < made.size(); ++b)
        {
            const double d = layoutDistance(made[a], made[b], Catalog::builtin());
            if (d < closest)
            {
                closest = d;
                closestPair = made[a].id + " and " + made[b].id;
            }
        }

    const double median = percentile(seconds, 0.5);
    const double p95 = percentile(seconds, 0.95);
    const double toppleShare = pigs > 0 ? static_cast<double>(toppled) / pigs : 0.0;
    std::ostringstream md;
    md << "# bench generate\n\n"
       << seeds << " seeds (1 to " << seeds << "), loss share 0.1, 0.3, 0.5, 0.7, 0.9 in turn, 40 model-player runs "
       << "per measure, every core. " << loadAverageNote() << "\n\n"
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
       << ") | > 0: no two alike |\n"
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
