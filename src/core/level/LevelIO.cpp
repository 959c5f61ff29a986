#include "level/JsonLocator.hpp"
#include "level/LevelReader.hpp"

#include <abalike/level/LevelIO.hpp>
#include <abalike/world/Catalog.hpp>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace abalike
{

namespace
{

using json = nlohmann::json;

constexpr std::size_t kMaxLevelBytes = 4u << 20; // a large level is a few kB
constexpr int kMaxNesting = 64;                  // a level nests 4 deep
constexpr double kInf = std::numeric_limits<double>::infinity();

/// Box2D simulates moving bodies of 0.1 to 10 m and static ones up to 50 m well; the world should stay within
/// about 2 km of the origin.
constexpr double kMinBodySize = 0.1;
constexpr double kMaxBodySize = 10.0;
constexpr double kMaxStaticSize = 50.0;
constexpr double kWorldExtent = 2000.0;

std::vector<std::string> names(const auto& items)
{
    std::vector<std::string> out;
    for (const auto& item : items)
        out.push_back(item.name);
    return out;
}

std::string oneOf(const std::vector<std::string>& options)
{
    std::string out;
    for (std::size_t i = 0; i < options.size(); ++i)
        out += (i == 0 ? "" : ", ") + options[i];
    return out;
}

/// Checks a name against the catalog's, with a suggestion for typos.
void checkName(LevelReader& reader, const std::string& pointer, const std::string& what, const std::string& name,
               const std::vector<std::string>& known)
{
    if (std::find(known.begin(), known.end(), name) != known.end())
        return;
    std::string message = "unknown " + what + " \"" + name + "\"";
    if (const auto suggestion = closestMatch(name, known))
        message += " (did you mean \"" + *suggestion + "\"?)";
    else
        message += " (expected one of: " + oneOf(known) + ")";
    reader.error(pointer, message);
}

/// Deepest bracket nesting outside strings; stops counting once past the limit.
int nestingDepth(std::string_view text)
{
    int depth = 0;
    int deepest = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size() && deepest <= kMaxNesting; ++i)
    {
        const char c = text[i];
        if (inString)
        {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
        }
        else if (c == '"')
            inString = true;
        else if (c == '{' || c == '[')
            deepest = std::max(deepest, ++depth);
        else if (c == '}' || c == ']')
            --depth;
    }
    return deepest;
}

/// nlohmann reports the byte after the offending token; editors want its first character.
std::size_t tokenStart(std::string_view text, std::size_t byteAfter)
{
    std::size_t end = std::min(byteAfter, text.size());
    if (end == 0)
        return 0;
    std::size_t i = end - 1;
    if (text[i] == '"')
    {
        // Back to the opening quote of this string.
        while (i > 0 && !(text[i - 1] == '"' && (i < 2 || text[i - 2] != '\\')))
            --i;
        return i > 0 ? i - 1 : 0;
    }
    while (i > 0 && (std::isalnum(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '.' ||
                     text[i - 1] == '-' || text[i - 1] == '+'))
        --i;
    return i;
}

void readBlocks(LevelReader& r, const json& root, LevelDef& level, const Catalog& catalog)
{
    const auto it = root.find("blocks");
    if (it == root.end() || !r.array(*it, "/blocks"))
        return;
    const auto materials = names(catalog.materials());
    for (std::size_t i = 0; i < it->size(); ++i)
    {
        const json& b = (*it)[i];
        const std::string p = "/blocks/" + std::to_string(i);
        if (!r.object(b, p, {"shape", "material", "x", "y", "w", "h", "angle_deg"}))
            continue;
        BlockDef block;
        const std::string shape = r.string(b, p, "shape", "box", false);
        if (shape == "box")
            block.shape = BlockShape::Box;
        else if (shape == "circle")
            block.shape = BlockShape::Circle;
        else if (shape == "triangle")
            block.shape = BlockShape::Triangle;
        else
            r.error(p + "/shape", "unknown shape \"" + shape + "\" (expected box, circle or triangle)");
        block.material = r.string(b, p, "material", "wood", true);
        checkName(r, p + "/material", "material", block.material, materials);
        block.x = r.number(b, p, "x", 0.0, true, -kWorldExtent, kWorldExtent);
        block.y = r.number(b, p, "y", 0.0, true, -kWorldExtent, kWorldExtent);
        block.widthM = r.number(b, p, "w", 1.0, true, kMinBodySize, kMaxBodySize);
        block.heightM = r.number(b, p, "h", 1.0, block.shape != BlockShape::Circle, kMinBodySize, kMaxBodySize);
        if (block.shape == BlockShape::Circle)
            block.heightM = block.widthM;
        block.angleDeg = r.number(b, p, "angle_deg", 0.0, false, -360.0, 360.0);
        level.blocks.push_back(block);
    }
}

void readPigs(LevelReader& r, const json& root, LevelDef& level, const Catalog& catalog)
{
    const auto it = root.find("pigs");
    if (it == root.end())
    {
        r.error("", "missing required key \"pigs\" (expected an array with at least one pig)");
        return;
    }
    if (!r.array(*it, "/pigs"))
        return;
    if (it->empty())
        r.error("/pigs", "a level needs at least one pig (got an empty array)");
    const auto pigTypes = names(catalog.pigs());
    for (std::size_t i = 0; i < it->size(); ++i)
    {
        const json& g = (*it)[i];
        const std::string p = "/pigs/" + std::to_string(i);
        if (!r.object(g, p, {"type", "x", "y"}))
            continue;
        PigDef pig;
        pig.type = r.string(g, p, "type", "small", false);
        checkName(r, p + "/type", "pig type", pig.type, pigTypes);
        pig.x = r.number(g, p, "x", 0.0, true, -kWorldExtent, kWorldExtent);
        pig.y = r.number(g, p, "y", 0.0, true, -kWorldExtent, kWorldExtent);
        level.pigs.push_back(pig);
    }
}

void readTerrain(LevelReader& r, const json& root, LevelDef& level)
{
    const auto it = root.find("terrain");
    if (it == root.end() || !r.array(*it, "/terrain"))
        return;
    for (std::size_t i = 0; i < it->size(); ++i)
    {
        const json& t = (*it)[i];
        const std::string p = "/terrain/" + std::to_string(i);
        if (!r.object(t, p, {"x", "y", "w", "h", "angle_deg"}))
            continue;
        TerrainDef terrain;
        terrain.x = r.number(t, p, "x", 0.0, true, -kWorldExtent, kWorldExtent);
        terrain.y = r.number(t, p, "y", 0.0, true, -kWorldExtent, kWorldExtent);
        terrain.widthM = r.number(t, p, "w", 1.0, true, kMinBodySize, kMaxStaticSize);
        terrain.heightM = r.number(t, p, "h", 1.0, true, kMinBodySize, kMaxStaticSize);
        terrain.angleDeg = r.number(t, p, "angle_deg", 0.0, false, -360.0, 360.0);
        level.terrain.push_back(terrain);
    }
}

void readBirds(LevelReader& r, const json& root, LevelDef& level, const Catalog& catalog)
{
    const auto it = root.find("birds");
    if (it == root.end())
    {
        r.error("", "missing required key \"birds\" (expected an array of bird names)");
        return;
    }
    if (!r.array(*it, "/birds"))
        return;
    if (it->empty())
        r.error("/birds", "a level needs at least one bird (got an empty array)");
    const auto birdTypes = names(catalog.birds());
    for (std::size_t i = 0; i < it->size(); ++i)
    {
        const std::string p = "/birds/" + std::to_string(i);
        if (!(*it)[i].is_string())
        {
            r.error(p, "expected a bird name (" + oneOf(birdTypes) + "), got " + describeJsonType((*it)[i]));
            continue;
        }
        const std::string name = (*it)[i].get<std::string>();
        checkName(r, p, "bird", name, birdTypes);
        level.birds.push_back(name);
    }
}

void readEnvironment(LevelReader& r, const json& root, LevelDef& level)
{
    const auto it = root.find("environment");
    if (it == root.end() || !r.object(*it, "/environment", {"gravity", "air_density", "wind"}))
        return;
    EnvironmentDef& env = level.environment;
    env.gravity = r.number(*it, "/environment", "gravity", 9.81, false, 0.0, 1000.0);
    env.airDensity = r.number(*it, "/environment", "air_density", 0.0, false, 0.0, 100.0);
    if (const auto wind = it->find("wind"); wind != it->end())
    {
        if (!wind->is_array() || wind->size() != 2 || !(*wind)[0].is_number() || !(*wind)[1].is_number())
            r.error("/environment/wind", "expected [wx, wy] in m/s, got " + describeJsonType(*wind));
        else
        {
            env.windX = (*wind)[0].get<double>();
            env.windY = (*wind)[1].get<double>();
        }
    }
}

void readStars(LevelReader& r, const json& root, LevelDef& level)
{
    const auto it = root.find("stars");
    if (it == root.end())
        return;
    if (!it->is_array() || it->size() != 3)
    {
        r.error("/stars", "expected three increasing scores [one, two, three], got " + describeJsonType(*it));
        return;
    }
    for (std::size_t i = 0; i < 3; ++i)
    {
        const json& v = (*it)[i];
        if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > 100000000)
        {
            r.error("/stars/" + std::to_string(i), "expected a whole score >= 0, got " + describeJsonType(v));
            return;
        }
        level.starScores[i] = static_cast<int>(v.get<long long>());
    }
    if (!(level.starScores[0] <= level.starScores[1] && level.starScores[1] <= level.starScores[2]))
        r.error("/stars", "star scores must not decrease (one <= two <= three)");
}

void readHints(LevelReader& r, const json& root, LevelDef& level)
{
    const auto it = root.find("hints");
    if (it == root.end() || !r.array(*it, "/hints"))
        return;
    for (std::size_t i = 0; i < it->size(); ++i)
    {
        if ((*it)[i].is_string())
            level.hints.push_back((*it)[i].get<std::string>());
        else
            r.error("/hints/" + std::to_string(i), "expected a string, got " + describeJsonType((*it)[i]));
    }
}

} // namespace

std::string LevelIssue::format() const
{
    std::ostringstream out;
    out << file << ':' << line << ':' << column << ": error: " << (pointer.empty() ? "/" : pointer) << ": " << message;
    return out.str();
}

LevelLoadError::LevelLoadError(std::vector<LevelIssue> issues)
    : std::runtime_error(issues.empty() ? std::string("invalid level") : issues.front().format()),
      m_issues(std::move(issues))
{
}

LevelDef parseLevel(std::string_view text, const std::string& fileName, const Catalog& catalog)
{
    auto fail = [&](int line, int column, const std::string& message) {
        throw LevelLoadError({LevelIssue{fileName, line, column, "", message}});
    };
    if (text.size() > kMaxLevelBytes)
        fail(1, 1, "file is " + std::to_string(text.size()) + " bytes (expected a level of at most " +
                       std::to_string(kMaxLevelBytes) + " bytes)");
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
        fail(1, 1, "empty file (expected a JSON object describing a level)");
    if (nestingDepth(text) > kMaxNesting)
        fail(1, 1, "JSON nested more than " + std::to_string(kMaxNesting) + " levels deep (a level needs 4)");

    json root;
    try
    {
        root = json::parse(text);
    }
    catch (const json::parse_error& e)
    {
        const auto [line, column] = JsonLocator::lineColumn(text, tokenStart(text, e.byte));
        std::string what = e.what();
        // nlohmann prefixes "[json.exception.parse_error.101] parse error at line 1, column 2: "; keep the reason.
        if (const auto colon = what.find(": "); colon != std::string::npos)
            what = what.substr(colon + 2);
        fail(line, column, "invalid JSON: " + what);
    }
    catch (const json::exception& e)
    {
        fail(1, 1, std::string("invalid JSON: ") + e.what());
    }

    const JsonLocator locator(text);
    LevelReader r(fileName, locator);
    LevelDef level;
    level.sourcePath = fileName;
    if (!r.object(root, "", {"$schema", "format", "id", "title", "concept", "hints", "ground", "slingshot", "birds",
                             "blocks", "pigs", "terrain", "environment", "stars"}))
        throw LevelLoadError(r.take());

    const double format = r.number(root, "", "format", 1.0, true, 1.0, 1.0);
    (void)format;
    level.id = r.string(root, "", "id", "", true);
    level.title = r.string(root, "", "title", "", true);
    level.lesson = r.string(root, "", "concept", "", false);
    readHints(r, root, level);
    if (const auto ground = root.find("ground"); ground != root.end() && r.object(*ground, "/ground", {"y"}))
        level.groundY = r.number(*ground, "/ground", "y", 0.0, false, -kWorldExtent, kWorldExtent);
    if (const auto sling = root.find("slingshot"); sling == root.end())
        r.error("", "missing required key \"slingshot\" (expected {\"x\", \"y\", \"max_force_n\"})");
    else if (r.object(*sling, "/slingshot", {"x", "y", "max_force_n"}))
    {
        level.slingshot.x = r.number(*sling, "/slingshot", "x", 0.0, true, -kWorldExtent, kWorldExtent);
        level.slingshot.y = r.number(*sling, "/slingshot", "y", 1.5, true, -kWorldExtent, kWorldExtent);
        level.slingshot.maxForceN = r.number(*sling, "/slingshot", "max_force_n", 1200.0, false, 1.0, 1.0e6);
    }
    readBirds(r, root, level, catalog);
    readBlocks(r, root, level, catalog);
    readPigs(r, root, level, catalog);
    readTerrain(r, root, level);
    readEnvironment(r, root, level);
    readStars(r, root, level);

    if (!r.ok())
        throw LevelLoadError(r.take());
    return level;
}

LevelDef loadLevel(const std::string& path, const Catalog& catalog)
{
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw LevelLoadError({LevelIssue{path, 0, 0, "", "is a directory (expected a level .json file)"}});
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw LevelLoadError({LevelIssue{path, 0, 0, "", "cannot open file (does it exist and is it readable?)"}});
    std::string text;
    char buffer[65536];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
    {
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
        if (text.size() > kMaxLevelBytes)
            break; // parseLevel reports the size; no need to read a huge file to the end
    }
    return parseLevel(text, path, catalog);
}

std::vector<std::string> loadCampaign(const std::string& manifestPath)
{
    std::ifstream in(manifestPath, std::ios::binary);
    if (!in)
        throw LevelLoadError({LevelIssue{manifestPath, 0, 0, "", "cannot open campaign manifest"}});
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    json root;
    try
    {
        root = json::parse(text);
    }
    catch (const json::exception& e)
    {
        throw LevelLoadError({LevelIssue{manifestPath, 0, 0, "", std::string("invalid JSON: ") + e.what()}});
    }
    const JsonLocator locator(text);
    LevelReader r(manifestPath, locator);
    std::vector<std::string> paths;
    const auto folder = std::filesystem::path(manifestPath).parent_path();
    if (r.object(root, "", {"$schema", "format", "title", "episodes"}))
    {
        const auto episodes = root.find("episodes");
        if (episodes == root.end())
            r.error("", "missing required key \"episodes\"");
        else if (r.array(*episodes, "/episodes"))
        {
            for (std::size_t e = 0; e < episodes->size(); ++e)
            {
                const json& episode = (*episodes)[e];
                const std::string p = "/episodes/" + std::to_string(e);
                if (!r.object(episode, p, {"id", "title", "levels"}))
                    continue;
                const auto levels = episode.find("levels");
                if (levels == episode.end() || !r.array(*levels, p + "/levels"))
                    continue;
                for (std::size_t l = 0; l < levels->size(); ++l)
                {
                    if ((*levels)[l].is_string())
                        paths.push_back((folder / (*levels)[l].get<std::string>()).string());
                    else
                        r.error(p + "/levels/" + std::to_string(l), "expected a level file name");
                }
            }
        }
    }
    if (!r.ok())
        throw LevelLoadError(r.take());
    return paths;
}

} // namespace abalike
