#include "cli/Commands.hpp"
#include "cli/SolutionJson.hpp"
#include "cli/UsageError.hpp"
#include "shell/DataPaths.hpp"

#include <abalike/design/Generator.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/level/SafeText.hpp>
#include <abalike/save/AtomicWrite.hpp>

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

namespace abalike::app
{

namespace
{

struct GenerateArgs
{
    std::uint64_t seed = 1;
    double lossShare = 0.5;
    std::size_t count = 1;
    std::string birds;
    std::string world = "earth";
    std::string outDir;
    std::string outFile;
    bool json = false;
    int threads = 0;
    std::size_t playerRuns = 40;
};

std::vector<std::string> splitBirds(const std::string& list)
{
    std::vector<std::string> birds;
    std::stringstream in(list);
    std::string bird;
    while (std::getline(in, bird, ','))
        if (!bird.empty())
            birds.push_back(bird);
    return birds;
}

std::map<std::string, int> rejectionCounts(const GeneratedLevel& g)
{
    std::map<std::string, int> counts{{"fell", 0}, {"unwinnable", 0}, {"too easy", 0}, {"too hard", 0}};
    for (const Rejection r : g.rejected)
        ++counts[rejectionName(r)];
    return counts;
}

std::string rejectionText(const GeneratedLevel& g)
{
    std::string text;
    for (const auto& [reason, count] : rejectionCounts(g))
        if (count > 0)
            text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + reason;
    return text.empty() ? "none rejected" : text + " rejected";
}

std::filesystem::path levelSchema()
{
    return std::filesystem::path(levelsDirectory()) / "schema" / "level.schema.json";
}

/// The pack's manifest: one episode with the levels in seed order, pointing at the bundled campaign schema.
std::string packManifest(const std::filesystem::path& dir, const std::vector<std::string>& files, const GenerateArgs& a)
{
    nlohmann::ordered_json manifest;
    const std::filesystem::path schema = std::filesystem::path(levelsDirectory()) / "schema" / "campaign.schema.json";
    manifest["$schema"] = schemaReferenceFor(dir / "campaign.json", schema);
    manifest["format"] = 1;
    manifest["title"] = "Generated castles " + std::to_string(a.seed) + "-" + std::to_string(a.seed + a.count - 1);
    manifest["episodes"] = nlohmann::ordered_json::array();
    manifest["episodes"].push_back({{"id", "1"}, {"title", "Generated castles"}, {"levels", files}});
    return manifest.dump(2) + "\n";
}

int runGenerate(const GenerateArgs& a)
{
    if (a.lossShare < 0.0 || a.lossShare > 1.0)
        throw UsageError("--loss-share: expected 0 (every try wins) to 1 (almost none does), got " +
                         shortestNumber(a.lossShare));
    if (a.count < 1 || a.count > 1000)
        throw UsageError("--count: expected 1 to 1000 levels, got " + std::to_string(a.count));
    if (a.count > 1 && a.outDir.empty())
        throw UsageError("--count " + std::to_string(a.count) + ": give --out DIR for a level pack");
    if (!a.outDir.empty() && !a.outFile.empty())
        throw UsageError("give --out DIR (a level pack) or -o FILE.json (one level), not both");
    if (a.threads < 0 || a.threads > 256)
        throw UsageError("--threads: expected 0 (all cores) to 256, got " + std::to_string(a.threads));

    const std::string partsDir = (std::filesystem::path(levelsDirectory()) / "parts").string();
    const std::vector<GeneratorPart> parts = loadGeneratorParts(partsDir, Catalog::builtin());
    GeneratorOptions options;
    options.lossShare = a.lossShare;
    options.birds = splitBirds(a.birds);
    options.world = a.world;
    options.threads = a.threads;
    options.playerRuns = a.playerRuns;
    if (!a.outDir.empty())
        std::filesystem::create_directories(a.outDir);

    nlohmann::ordered_json report;
    report["levels"] = nlohmann::ordered_json::array();
    std::vector<std::string> files;
    for (std::size_t i = 0; i < a.count; ++i)
    {
        options.seed = a.seed + i;
        GeneratedLevel g;
        try
        {
            g = generateLevel(parts, options, Catalog::builtin());
        }
        catch (const std::invalid_argument& e)
        {
            throw UsageError(e.what());
        }
        if (!g.ok)
        {
            std::cerr << "abalike: error: seed " << options.seed << ": no level passed in " << g.attempts
                      << " attempts (" << rejectionText(g) << "); try another seed or loss share\n";
            return 1;
        }
        std::filesystem::path path;
        if (!a.outDir.empty())
        {
            path = std::filesystem::path(a.outDir) / (g.level.id + ".json");
            g.level.episode = "1"; // the pack's one episode
        }
        else if (!a.outFile.empty())
            path = a.outFile;
        if (path.empty())
            std::cout << writeLevelJson(g.level, levelSchema().string());
        else
        {
            saveLevel(g.level, path, levelSchema());
            files.push_back(path.filename().string());
        }
        nlohmann::ordered_json row;
        row["seed"] = options.seed;
        row["file"] = path.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(path.string());
        row["kind"] = generatedKindName(g.kind);
        row["title"] = g.level.title;
        row["bodies"] = g.level.blocks.size() + g.level.pigs.size();
        row["birds"] = g.level.birds;
        row["loss_share"] = g.lossShare;
        row["asked_loss_share"] = a.lossShare;
        row["attempts"] = g.attempts;
        row["rejected"] = rejectionCounts(g);
        row["solve"] = solutionToJson(g.level, g.solution);
        row["player"] = playerDifficultyJson(g.player);
        row["seconds"] = g.seconds;
        report["levels"].push_back(row);
        if (!a.json)
            std::cerr << g.level.id << " \"" << g.level.title << "\": " << generatedKindName(g.kind) << ", "
                      << row["bodies"].get<std::size_t>() << " bodies, " << g.level.birds.size()
                      << (g.level.birds.size() == 1 ? " bird" : " birds") << "; loss share " << std::fixed
                      << std::setprecision(2) << g.lossShare << " (asked " << a.lossShare << "), " << g.attempts
                      << " attempt(s), " << rejectionText(g) << ", " << std::setprecision(1) << g.seconds << " s"
                      << (path.empty() ? "" : " -> " + escapeForTerminal(path.string())) << '\n';
    }
    if (!a.outDir.empty())
        writeFileAtomically(std::filesystem::path(a.outDir) / "campaign.json", packManifest(a.outDir, files, a));
    if (a.json)
        std::cout << report.dump() << '\n';
    return 0;
}

} // namespace

CommandRunner addGenerateCommand(CLI::App& app)
{
    auto args = std::make_shared<GenerateArgs>();
    CLI::App* cmd = app.add_subcommand(
        "generate", "Generate levels from the campaign's castle parts, each verified (it stands, the solver wins it, "
                    "the model player loses about as often as asked) before it is written");
    cmd->add_option("--seed", args->seed, "seed of the first level (default 1); the same seed gives the same file");
    cmd->add_option("--loss-share", args->lossShare,
                    "share of the model player's tries that should lose, 0 to 1 (default 0.5; kept within 0.15)");
    cmd->add_option("--count", args->count, "levels to generate, seeds SEED, SEED+1, ... (default 1; needs --out)");
    cmd->add_option("--birds", args->birds, "the birds, e.g. red,black,red (default: chosen for the structure)");
    cmd->add_option("--world", args->world,
                    "earth, moon, mars, titan or jupiter: gravity, air and look (default earth)");
    cmd->add_option("--out", args->outDir, "write a level pack to DIR: campaign.json and its levels (play --pack DIR)");
    cmd->add_option("-o", args->outFile, "write the level to FILE.json (default: print it)");
    cmd->add_flag("--json", args->json, "print a JSON report of what was generated and measured");
    cmd->add_option("--threads", args->threads, "worker threads (default 0: every core)");
    cmd->add_option("--player-runs", args->playerRuns, "plays of the model player per measure (default 40)");
    return [args]
    {
        return runGenerate(*args);
    };
}

} // namespace abalike::app
