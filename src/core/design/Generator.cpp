#include <abalike/design/Generator.hpp>

#include <abalike/design/GeneratorLayouts.hpp>

#include <abalike/design/StarThresholds.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/world/RestCheck.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <set>
#include <stdexcept>

namespace abalike
{

std::vector<GeneratorPart> loadGeneratorParts(const std::string& folder, const Catalog& catalog)
{
    std::vector<GeneratorPart> parts;
    for (const std::string& file : levelFilesIn(folder))
        parts.push_back({std::filesystem::path(file).stem().string(), loadLevel(file, catalog)});
    return parts;
}

const char* rejectionName(Rejection rejection)
{
    switch (rejection)
    {
    case Rejection::Fell:
        return "fell";
    case Rejection::Unwinnable:
        return "unwinnable";
    case Rejection::TooEasy:
        return "too easy";
    case Rejection::TooHard:
        return "too hard";
    }
    return "fell";
}

namespace
{

/// The bird each material calls for (the birds' roles): stone the black bird's blast, ice the blue bird's split,
/// wood the yellow bird's boost; TNT any bird.
std::string birdFor(const std::string& material)
{
    if (material == "stone")
        return "black";
    if (material == "ice")
        return "blue";
    if (material == "wood")
        return "yellow";
    return "red";
}

/// n birds: red first and every other one, between them the birds of the structure's materials, commonest first.
std::vector<std::string> birdsFor(const LevelDef& level, int n)
{
    std::map<std::string, int> count;
    for (const BlockDef& block : level.blocks)
        ++count[block.material];
    std::vector<std::pair<int, std::string>> byCount;
    for (const auto& [material, blocks] : count)
        byCount.emplace_back(-blocks, material);
    std::sort(byCount.begin(), byCount.end());
    std::vector<std::string> roles;
    for (const auto& [negated, material] : byCount)
        if (std::find(roles.begin(), roles.end(), birdFor(material)) == roles.end())
            roles.push_back(birdFor(material));
    if (roles.empty())
        roles.push_back("red");
    std::vector<std::string> birds;
    for (int i = 0; i < n; ++i)
        birds.push_back(i % 2 == 0 ? "red" : roles[static_cast<std::size_t>(i / 2) % roles.size()]);
    return birds;
}

/// "Castle 4711", "TNT store 12": the title names the kind and the seed that replays it.
std::string titleOf(GeneratedKind kind, std::uint64_t seed)
{
    std::string name = kind == GeneratedKind::TntStore ? "TNT store" : generatedKindName(kind);
    name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
    return name + " " + std::to_string(seed);
}

/// Thrown from the solver's and the model player's progress reports when GeneratorOptions::stop is set.
struct GenerationStopped
{
};

void throwIfStopped(const GeneratorOptions& options)
{
    if (options.stop != nullptr && options.stop->load(std::memory_order_relaxed))
        throw GenerationStopped{};
}

/// The verdict of one measure of a laid-out level with its birds.
struct Measure
{
    std::optional<Rejection> rejection;
    Solution solution;
    PlayerDifficulty player;
    double lossShare = 0.0;
};

/// The solver and the model player on a level that stands.
Measure measure(const LevelDef& level, const GeneratorOptions& options, const Catalog& catalog)
{
    Measure m;
    const auto stopCheck = [&options](std::size_t, std::size_t)
    {
        throwIfStopped(options);
    };
    SolverOptions solver;
    const int threads = options.threadsNow != nullptr ? options.threadsNow->load() : options.threads;
    solver.threads = threads;
    solver.progress = stopCheck;
    m.solution = solveLevel(level, catalog, solver);
    if (!m.solution.outcome.won)
    {
        m.rejection = Rejection::Unwinnable;
        return m;
    }
    ModelPlayerOptions player;
    player.runs = options.playerRuns;
    player.seed = options.seed;
    player.threads = threads;
    player.progress = stopCheck;
    m.player = measurePlayerDifficulty(level, catalog, player);
    m.lossShare = 1.0 - m.player.winShare;
    if (m.lossShare > options.lossShare + GeneratorOptions::kLossTolerance)
        m.rejection = Rejection::TooHard;
    else if (m.lossShare < options.lossShare - GeneratorOptions::kLossTolerance)
        m.rejection = Rejection::TooEasy;
    return m;
}

void generateInto(GeneratedLevel& result, const LevelDef& world, const std::vector<GeneratorPart>& parts,
                  const GeneratorOptions& options, const Catalog& catalog)
{
    const bool autoBirds = options.birds.empty();
    int layoutIndex = 0;
    while (result.attempts < options.maxAttempts)
    {
        throwIfStopped(options);
        GeneratorRng rng(options.seed, static_cast<std::uint64_t>(layoutIndex++));
        LevelDef level = world;
        level.format = 1;
        level.id = "generated-" + std::to_string(options.seed);
        const GeneratedKind kind = layOut(level, parts, rng, catalog);
        level.title = titleOf(kind, options.seed);
        level.hints = {kindHint(kind)};
        if (!checkRest(level, catalog).passed())
        {
            ++result.attempts;
            result.rejected.push_back(Rejection::Fell);
            continue; // the birds do not change whether it stands
        }
        const int pigs = static_cast<int>(level.pigs.size());
        int birds = autoBirds ? std::clamp((pigs + 1) / 2 + 1, 1, GeneratorOptions::kMaxBirds) : 0;
        std::set<int> tried;
        while (result.attempts < options.maxAttempts)
        {
            ++result.attempts;
            level.birds = autoBirds ? birdsFor(level, birds) : options.birds;
            tried.insert(birds);
            Measure m = measure(level, options, catalog);
            if (!m.rejection)
            {
                level.referenceShot =
                    ReferenceShotDef{m.solution.shots.front().angleDeg, m.solution.shots.front().speedMps};
                level.starScores = recommendedStars(m.player, m.solution.outcome.score);
                result.ok = true;
                result.level = level;
                result.kind = kind;
                result.solution = std::move(m.solution);
                result.player = std::move(m.player);
                result.lossShare = m.lossShare;
                return;
            }
            result.rejected.push_back(*m.rejection);
            // With automatic birds a level too hard or unwinnable gets one more bird, one too easy one fewer, as long
            // as that count was not tried on this layout; otherwise the next layout.
            int next = birds;
            if (*m.rejection == Rejection::TooHard || *m.rejection == Rejection::Unwinnable)
                next = birds + 1;
            else if (*m.rejection == Rejection::TooEasy)
                next = birds - 1;
            if (!autoBirds || next == birds || next < 1 || next > GeneratorOptions::kMaxBirds || tried.count(next))
                break;
            birds = next;
        }
    }
}

} // namespace

std::optional<LevelDef> generateStructure(const std::vector<GeneratorPart>& parts, GeneratedKind kind, int maxBodies,
                                          std::uint64_t seed, const Catalog& catalog)
{
    for (std::uint64_t stream = 0; stream < 8; ++stream)
    {
        GeneratorRng rng(seed, stream);
        LevelDef structure;
        structure.sandbox = true;
        layOut(structure, parts, rng, catalog, kind, maxBodies);
        if (checkRest(structure, catalog).passed())
            return structure;
    }
    return std::nullopt;
}

GeneratedLevel generateLevel(const std::vector<GeneratorPart>& parts, const GeneratorOptions& options,
                             const Catalog& catalog)
{
    if (parts.empty())
        throw std::invalid_argument("no castle parts to build with (levels/parts/ is empty or missing)");
    for (const std::string& bird : options.birds)
        if (catalog.findBird(bird) == nullptr)
            throw std::invalid_argument("unknown bird \"" + bird + "\" (expected red, blue, yellow, black or white)");
    LevelDef world;
    applyGeneratorWorld(world, options.world); // throws for an unknown world before any work

    const auto start = std::chrono::steady_clock::now();
    GeneratedLevel result;
    try
    {
        generateInto(result, world, parts, options, catalog);
    }
    catch (const GenerationStopped&)
    {
        result = GeneratedLevel{};
        result.stopped = true;
    }
    result.seed = options.seed;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace abalike
