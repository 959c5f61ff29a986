#include <abalike/level/ScienceBirds.hpp>

#include <abalike/level/LevelWriter.hpp>
#include <abalike/world/Catalog.hpp>
#include <abalike/world/RestFindings.hpp>

#include "level/FlatBottoms.hpp"
#include "level/LevelReader.hpp"
#include "level/Outline.hpp"
#include "level/XmlText.hpp"
#include <abalike/level/LevelLimits.hpp>
#include <abalike/level/PushApart.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>
#include <optional>
#include <pugixml.hpp>

namespace abalike
{

namespace
{

/// A Science Birds block prefab: its shape and size at rotation 0 (Science Birds' level generators list the same).
struct Piece
{
    const char* name;
    BlockShape shape;
    double widthM;
    double heightM;
};

constexpr Piece kPieces[] = {
    {"SquareHole", BlockShape::HollowBox, 0.84, 0.84}, {"RectFat", BlockShape::Box, 0.85, 0.43},
    {"SquareSmall", BlockShape::Box, 0.43, 0.43},      {"SquareTiny", BlockShape::Box, 0.22, 0.22},
    {"RectTiny", BlockShape::Box, 0.43, 0.22},         {"RectSmall", BlockShape::Box, 0.85, 0.22},
    {"RectMedium", BlockShape::Box, 1.68, 0.22},       {"RectBig", BlockShape::Box, 2.06, 0.22},
    {"Circle", BlockShape::Circle, 0.8, 0.8},          {"CircleSmall", BlockShape::Circle, 0.45, 0.45},
    {"Triangle", BlockShape::Triangle, 0.82, 0.82},    {"TriangleHole", BlockShape::Triangle, 0.82, 0.82},
};

/// SquareHole's round hole (about 0.5 m across) becomes a square one of the same width.
constexpr double kSquareHoleWallM = 0.17;
constexpr double kTntSizeM = 0.55;
constexpr double kPlatformTileM = 0.62;
constexpr double kDefaultSlingshotX = -8.0;
constexpr double kDefaultSlingshotY = -2.5;
constexpr int kDefaultBirds = 3;

const std::map<std::string, std::string> kBirds = {
    {"BirdRed", "red"}, {"BirdBlue", "blue"}, {"BirdYellow", "yellow"}, {"BirdBlack", "black"}, {"BirdWhite", "white"}};
/// Science Birds' pigs become our types of their size (assets/catalog.json): sb-medium and sb-large are as tall as
/// its pigs (0.76 and 0.97 m), sb-small 0.43 m against its 0.45: its pig has a flat top that carries a plank laid
/// across 0.43 m posts beside it, which a round pig cannot, so ours fits under that plank instead.
const std::map<std::string, std::string> kPigs = {
    {"BasicSmall", "sb-small"}, {"BasicMedium", "sb-medium"}, {"BasicBig", "sb-large"}};
/// Half the height of each Science Birds pig's collider: a pig keeps its bottom where it was in the file.
const std::map<std::string, double> kPigHalfHeights = {{"sb-small", 0.225}, {"sb-medium", 0.38}, {"sb-large", 0.485}};

std::vector<std::string> keysOf(const std::map<std::string, std::string>& names)
{
    std::vector<std::string> keys;
    for (const auto& entry : names)
        keys.push_back(entry.first);
    return keys;
}

/// "(did you mean "RectSmall"?)" when one name is close to what was written, else "(expected one of A, B, ...)".
std::string expectedName(const std::string& written, const std::vector<std::string>& names)
{
    if (const std::optional<std::string> suggestion = closestMatch(written, names))
        return "(did you mean \"" + *suggestion + "\"?)";
    std::string text;
    for (const std::string& name : names)
        text.append(text.empty() ? "" : ", ").append(name);
    return "(expected one of " + text + ")";
}

/// The objects Science Birds' own levels are made of, inside <GameObjects>.
const std::vector<std::string> kStandardObjects = {"Block", "Pig", "TNT", "Platform"};

/// How far from square a rotation is still read as square. Science Birds' levels are often snapshots of a scene
/// that settled (generator outputs record 359.6 or 88.7): ours start as written, and a stack tilted by a degree
/// stands on corners and slides. Of the 33 700 block rotations in the pinned corpus (tools/science-birds-corpus.json)
/// 2 427 are 1-5 degrees off square and none 5-11: deliberate tilts are larger.
constexpr double kSquareWithinDeg = 5.0;

/// The rotation in (-180, 180], and a multiple of 90 when within kSquareWithinDeg of one.
double cleanAngle(double degrees)
{
    double angle = std::fmod(degrees, 360.0);
    if (angle > 180.0)
        angle -= 360.0;
    if (angle <= -180.0)
        angle += 360.0;
    const double quarter = std::round(angle / 90.0) * 90.0;
    if (std::abs(angle - quarter) < kSquareWithinDeg)
        return quarter == -0.0 ? 0.0 : quarter;
    return std::round(angle * 1000.0) / 1000.0;
}

/// Reads one XML file into a level, collecting warnings and errors at their places.
class Importer
{
public:
    Importer(const std::string& fileName, const Catalog& catalog, const ScienceBirdsOptions& options)
        : m_file(fileName), m_catalog(catalog), m_options(options)
    {
    }

    ScienceBirdsLevel run(std::string_view bytes);

private:
    LevelIssue issueAt(std::size_t offset, const std::string& pointer, std::string message) const
    {
        const TextPlace place = placeOf(m_original, offsetBeforeRepair(offset, m_closed));
        return {m_file, place.line, place.column, pointer, std::move(message)};
    }
    std::size_t offsetOf(const pugi::xml_node& node) const
    {
        const std::ptrdiff_t offset = node.offset_debug();
        return offset > 0 ? static_cast<std::size_t>(offset - 1) : 0; // the '<' before the name
    }
    void warn(const pugi::xml_node& node, const std::string& pointer, std::string message)
    {
        m_warnings.push_back(issueAt(offsetOf(node), pointer, std::move(message)));
    }
    void fail(const pugi::xml_node& node, std::string message)
    {
        m_errors.push_back(issueAt(offsetOf(node), "", std::move(message)));
    }

    /// A warning at the element a body was read from.
    void warnAt(const std::string& pointer, std::string message)
    {
        m_warnings.push_back(issueAt(m_placeOf.count(pointer) ? m_placeOf[pointer] : 0, pointer, std::move(message)));
    }

    std::optional<double> number(const pugi::xml_node& node, const char* name, std::optional<double> fallback,
                                 const std::string& pointer);
    void readBirds(const pugi::xml_node& level);
    void readSlingshot(const pugi::xml_node& level);
    void readObjects(const pugi::xml_node& objects);
    void readBlock(const pugi::xml_node& node);
    void readPig(const pugi::xml_node& node);
    void readTnt(const pugi::xml_node& node);
    void readPlatform(const pugi::xml_node& node);
    void thickenThinPlatform(const pugi::xml_node& node, const std::string& pointer, TerrainDef& platform);
    /// Science Birds' y with its ground at -3.5 to ours at 0, to the millimetre (its files give centimetres, and
    /// generators write float noise such as 4.509999 for 4.51).
    static double ourY(double y) { return tidy(y - kScienceBirdsGroundY); }
    static double tidy(double metres) { return std::round(metres * 1e3) / 1e3; }
    /// cleanAngle, counting the rotations it made square (one warning says how many).
    double squared(double degrees)
    {
        const double angle = cleanAngle(degrees);
        double written = std::fmod(degrees, 360.0);
        written += written > 180.0 ? -360.0 : written <= -180.0 ? 360.0 : 0.0;
        if (std::abs(angle - written) > 1e-3 && std::fmod(angle, 90.0) == 0.0)
        {
            ++m_squaredRotations;
            m_mostSquaredDeg = std::max(m_mostSquaredDeg, std::abs(angle - written));
        }
        return angle;
    }
    /// A scene whose slingshot stands right of every pig (NovPhy's mirrored scenes) is mirrored: ours shoot rightwards.
    void shootToTheRight();
    void useOwnGround();
    /// Circles and pigs whose flat bottom stands on a platform's edge in Science Birds: moved onto it.
    void seatRoundBodies();
    /// Circles and pigs across two planks' ends: set into the gap, as they settle.
    void settleIntoGaps();
    void snapOntoSupports();
    /// Overlaps the snap leaves (a pig sunk into the pigs under it, a plank into a post beside it): pushed apart.
    void pushApart();
    void checkResult();

    std::string m_file;
    const Catalog& m_catalog;
    ScienceBirdsOptions m_options;
    std::string m_original; ///< the decoded text, before closing leaf tags (places refer to it)
    std::vector<ClosedTag> m_closed;
    LevelDef m_level;
    std::map<std::string, std::size_t> m_placeOf; ///< a body's pointer -> its element's offset
    std::vector<LevelIssue> m_warnings;
    std::vector<LevelIssue> m_errors;
    int m_squaredRotations = 0;
    double m_mostSquaredDeg = 0.0;
};

std::optional<double> Importer::number(const pugi::xml_node& node, const char* name, std::optional<double> fallback,
                                       const std::string& pointer)
{
    const pugi::xml_attribute attribute = node.attribute(name);
    const std::string element = node.name();
    if (attribute.empty())
    {
        if (!fallback)
        {
            fail(node, "<" + element + "> has no " + name + " (expected a number, e.g. " + name + "=\"1.5\")");
            return std::nullopt;
        }
        warn(node, pointer,
             "<" + element + "> has no " + name + "; read as " + name + "=\"" + shortestNumber(*fallback) + "\"");
        return fallback;
    }
    std::string_view text = attribute.value();
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t'))
        text.remove_suffix(1);
    if (!text.empty() && text.front() == '+')
        text.remove_prefix(1);
    // Science Birds parses numbers in the machine's language: a file written on a machine whose language writes a
    // decimal comma holds "-2,5", which loads there. One comma and no point reads as that decimal.
    std::string withPoint(text);
    const std::size_t comma = withPoint.find(',');
    if (comma != std::string::npos && withPoint.find_first_of(",.", comma + 1) == std::string::npos &&
        withPoint.find('.') == std::string::npos)
    {
        withPoint[comma] = '.';
        warn(node, pointer,
             "<" + element + "> " + name + "=\"" + attribute.value() + "\" has a decimal comma; read as " + name +
                 "=\"" + withPoint + "\" (as Science Birds does on a machine whose language writes decimal commas)");
        text = withPoint;
    }
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    {
        fail(node, "<" + element + "> " + name + "=\"" + attribute.value() + "\" is not a number (expected e.g. " +
                       name + "=\"1.5\")");
        return std::nullopt;
    }
    if (std::abs(value) > limits::kWorldExtentM)
    {
        fail(node, "<" + element + "> " + name + "=\"" + attribute.value() + "\" is outside the world (at most " +
                       std::to_string(static_cast<int>(limits::kWorldExtentM)) + " from the origin)");
        return std::nullopt;
    }
    return value;
}

void Importer::readBirds(const pugi::xml_node& level)
{
    const pugi::xml_node birds = level.child("Birds");
    if (birds)
    {
        for (const pugi::xml_node bird : birds.children("Bird"))
        {
            const std::string type = bird.attribute("type").value();
            const auto known = kBirds.find(type);
            if (known == kBirds.end())
                fail(bird,
                     "<Bird type=\"" + type + "\"> is not a Science Birds bird " + expectedName(type, keysOf(kBirds)));
            else if (m_level.birds.size() == limits::kMaxBirds)
                fail(bird, "more than " + std::to_string(limits::kMaxBirds) + " birds (a level has at most that many)");
            else
                m_level.birds.push_back(known->second);
        }
        if (m_level.birds.empty() && m_errors.empty())
            fail(birds, "<Birds> holds no <Bird type=\"BirdRed\"/> (a level needs at least one bird)");
        return;
    }
    // Older Science Birds levels give only a count of red birds.
    const pugi::xml_node amount = level.child("BirdsAmount");
    if (amount)
    {
        std::string_view text = amount.child_value();
        int count = 0;
        while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
            text.remove_prefix(1);
        while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
            text.remove_suffix(1);
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), count);
        if (error != std::errc() || end != text.data() + text.size() || count < 1 ||
            count > static_cast<int>(limits::kMaxBirds))
        {
            fail(amount, "<BirdsAmount> is \"" + std::string(amount.child_value()) +
                             "\" (expected a whole number of birds from 1 to " + std::to_string(limits::kMaxBirds) +
                             ")");
            return;
        }
        m_level.birds.assign(static_cast<std::size_t>(count), "red");
        return;
    }
    m_level.birds.assign(kDefaultBirds, "red");
    warn(level, "/birds", "no <Birds>: gave the level " + std::to_string(kDefaultBirds) + " red birds");
}

void Importer::readSlingshot(const pugi::xml_node& level)
{
    const pugi::xml_node slingshot = level.child("Slingshot");
    if (!slingshot)
    {
        warn(level, "/slingshot", "no <Slingshot>: placed it where Science Birds does, at x=\"-8\" y=\"-2.5\"");
        m_level.slingshot.x = kDefaultSlingshotX;
        m_level.slingshot.y = ourY(kDefaultSlingshotY);
        return;
    }
    const auto x = number(slingshot, "x", kDefaultSlingshotX, "/slingshot");
    const auto y = number(slingshot, "y", kDefaultSlingshotY, "/slingshot");
    if (x && y)
    {
        m_level.slingshot.x = *x;
        m_level.slingshot.y = ourY(*y);
    }
    m_placeOf["/slingshot"] = offsetOf(slingshot);
}

void Importer::readBlock(const pugi::xml_node& node)
{
    const std::string pointer = "/blocks/" + std::to_string(m_level.blocks.size());
    const std::string type = node.attribute("type").value();
    const Piece* piece = nullptr;
    for (const Piece& candidate : kPieces)
        if (type == candidate.name)
            piece = &candidate;
    if (piece == nullptr)
    {
        std::vector<std::string> names;
        for (const Piece& candidate : kPieces)
            names.push_back(candidate.name);
        fail(node, "<Block type=\"" + type + "\"> is not one of Science Birds' 12 blocks " + expectedName(type, names));
        return;
    }
    BlockDef block;
    block.shape = piece->shape;
    block.widthM = piece->widthM;
    block.heightM = piece->heightM;
    if (piece->shape == BlockShape::HollowBox)
        block.wallM = kSquareHoleWallM;
    if (type == "TriangleHole")
        warn(node, pointer, "a TriangleHole becomes a solid triangle (our blocks have no triangular hole)");
    if (node.attribute("material").empty())
    {
        warn(node, pointer, "<Block> has no material; read as material=\"wood\"");
        block.material = "wood";
    }
    else
    {
        block.material = node.attribute("material").value();
        std::transform(block.material.begin(), block.material.end(), block.material.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (block.material != "wood" && block.material != "ice" && block.material != "stone")
        {
            fail(node, "<Block material=\"" + std::string(node.attribute("material").value()) +
                           "\"> is not a Science Birds material (expected wood, ice or stone)");
            return;
        }
    }
    const auto x = number(node, "x", std::nullopt, pointer);
    const auto y = number(node, "y", std::nullopt, pointer);
    const auto rotation = number(node, "rotation", 0.0, pointer);
    if (!x || !y || !rotation)
        return;
    block.x = tidy(*x);
    block.y = ourY(*y);
    block.angleDeg = block.shape == BlockShape::Circle ? 0.0 : squared(*rotation);
    m_placeOf[pointer] = offsetOf(node);
    m_level.blocks.push_back(block);
}

void Importer::readPig(const pugi::xml_node& node)
{
    const std::string pointer = "/pigs/" + std::to_string(m_level.pigs.size());
    PigDef pig;
    if (node.attribute("type").empty())
    {
        warn(node, pointer, "<Pig> has no type; read as type=\"BasicSmall\"");
        pig.type = kPigs.at("BasicSmall");
    }
    else
    {
        const std::string type = node.attribute("type").value();
        const auto known = kPigs.find(type);
        if (known == kPigs.end())
        {
            fail(node, "<Pig type=\"" + type + "\"> is not a Science Birds pig " + expectedName(type, keysOf(kPigs)));
            return;
        }
        pig.type = known->second;
    }
    const auto x = number(node, "x", std::nullopt, pointer);
    const auto y = number(node, "y", std::nullopt, pointer);
    if (!x || !y)
        return;
    pig.x = tidy(*x);
    const PigType* ours = m_catalog.findPig(pig.type);
    pig.y = tidy(ourY(*y) - (ours != nullptr ? kPigHalfHeights.at(pig.type) - ours->radiusM : 0.0));
    m_placeOf[pointer] = offsetOf(node);
    m_level.pigs.push_back(pig);
}

void Importer::readTnt(const pugi::xml_node& node)
{
    const std::string pointer = "/blocks/" + std::to_string(m_level.blocks.size());
    const auto x = number(node, "x", std::nullopt, pointer);
    const auto y = number(node, "y", std::nullopt, pointer);
    const auto rotation = number(node, "rotation", 0.0, pointer);
    if (!x || !y || !rotation)
        return;
    BlockDef crate;
    crate.material = "tnt";
    crate.widthM = crate.heightM = kTntSizeM;
    crate.x = tidy(*x);
    crate.y = ourY(*y);
    crate.angleDeg = squared(*rotation);
    m_placeOf[pointer] = offsetOf(node);
    m_level.blocks.push_back(crate);
}

void Importer::readPlatform(const pugi::xml_node& node)
{
    const std::string pointer = "/terrain/" + std::to_string(m_level.terrain.size());
    const auto x = number(node, "x", std::nullopt, pointer);
    const auto y = number(node, "y", std::nullopt, pointer);
    const bool scaled = !node.attribute("scaleX").empty() || !node.attribute("scaleY").empty();
    // A platform without scales is one tile; Science Birds reads it so, without a word.
    const auto scaleX = scaled ? number(node, "scaleX", 1.0, pointer) : std::optional<double>(1.0);
    const auto scaleY = scaled ? number(node, "scaleY", 1.0, pointer) : std::optional<double>(1.0);
    const auto rotation =
        node.attribute("rotation").empty() ? std::optional<double>(0.0) : number(node, "rotation", 0.0, pointer);
    if (!x || !y || !scaleX || !scaleY || !rotation)
        return;
    // Science Birds (Unity) mirrors a platform with a negative scale and its collider keeps the size; one of scale 0
    // has no size and nothing rests on it.
    if (*scaleX == 0.0 || *scaleY == 0.0)
    {
        warn(node, "",
             "<Platform> has scaleX=\"" + shortestNumber(*scaleX) + "\" scaleY=\"" + shortestNumber(*scaleY) +
                 "\": no size, so nothing in Science Birds rests on it; left out");
        return;
    }
    if (*scaleX < 0.0 || *scaleY < 0.0)
        warn(node, pointer,
             "<Platform> has a negative scale (scaleX=\"" + shortestNumber(*scaleX) + "\" scaleY=\"" +
                 shortestNumber(*scaleY) + "\"): Science Birds mirrors it and keeps its size; read as " +
                 shortestNumber(std::abs(*scaleX)) + " by " + shortestNumber(std::abs(*scaleY)) + " tiles");
    TerrainDef platform;
    platform.x = tidy(*x);
    platform.y = ourY(*y);
    platform.widthM = tidy(kPlatformTileM * std::abs(*scaleX));
    platform.heightM = tidy(kPlatformTileM * std::abs(*scaleY));
    platform.angleDeg = squared(*rotation);
    thickenThinPlatform(node, pointer, platform);
    m_placeOf[pointer] = offsetOf(node);
    m_level.terrain.push_back(platform);
}

void Importer::thickenThinPlatform(const pugi::xml_node& node, const std::string& pointer, TerrainDef& platform)
{
    // Science Birds draws platforms of any scale; a static body thinner than limits::kMinBodySizeM is one our loader
    // refuses (Box2D's contacts need some thickness). Level or upright, it grows downwards so that what rests on its
    // top still does; tilted, about its centre.
    const double turn = std::remainder(platform.angleDeg, 180.0);
    const bool level = std::abs(turn) < 1e-9;
    const bool upright = std::abs(std::abs(turn) - 90.0) < 1e-9;
    for (double* size : {&platform.heightM, &platform.widthM})
    {
        if (*size >= limits::kMinBodySizeM)
            continue;
        const bool vertical = (size == &platform.heightM) ? level : upright;
        const double before = *size;
        if (vertical)
            platform.y = tidy(platform.y - 0.5 * (limits::kMinBodySizeM - before));
        *size = limits::kMinBodySizeM;
        warn(node, pointer,
             "<Platform> is " + shortestNumber(std::round(before * 1000.0) / 10.0) + " cm " +
                 (vertical ? "thick" : "wide") + ", less than the " + shortestNumber(limits::kMinBodySizeM * 100.0) +
                 " cm a static body needs to simulate well: made " + shortestNumber(limits::kMinBodySizeM * 100.0) +
                 " cm" + (vertical ? ", growing downwards (its top where it was)" : ", about its centre"));
    }
}

void Importer::readObjects(const pugi::xml_node& objects)
{
    for (const pugi::xml_node node : objects.children())
    {
        if (node.type() != pugi::node_element)
            continue;
        const std::string name = node.name();
        if (name == "Block")
            readBlock(node);
        else if (name == "Pig")
            readPig(node);
        else if (name == "TNT")
            readTnt(node);
        else if (name == "Platform")
            readPlatform(node);
        else if (const std::optional<std::string> typo = closestMatch(name, kStandardObjects))
            fail(node, "<" + name + "> is not a Science Birds object (did you mean <" + *typo + ">?)");
        else
            fail(node, "<" + name + "> is not one of Science Birds' standard objects (Block, Pig, TNT, Platform): " +
                           "a novelty object (as Phy-Q's and NovPhy's levels add) has nothing to become here");
    }
}

/// The lowest point of a body as placed: what it stands on is found from the bottom up.
double bottomOf(const BlockDef& b)
{
    if (b.shape == BlockShape::Circle)
        return b.y - 0.5 * b.widthM;
    if (b.shape == BlockShape::Triangle)
        return blockOutlines(b).front().bounds()[0].y;
    const double a = b.angleDeg * std::numbers::pi / 180.0;
    return b.y - 0.5 * (std::abs(b.widthM * std::sin(a)) + std::abs(b.heightM * std::cos(a)));
}

/// "2.0 cm": to the millimetre, or to a tenth of one where that would read the same as `than` (a gap of 20.04 cm
/// beside a limit of 20 cm reads "20.04 cm", never "20.0 cm ... more than the 20.0 cm").
std::string centimetres(double metres, double than = -1.0)
{
    const auto format = [](double m, int decimals)
    {
        char text[32];
        std::snprintf(text, sizeof text, "%.*f cm", decimals, std::abs(m) * 100.0);
        return std::string(text);
    };
    if (than >= 0.0 && format(metres, 1) == format(than, 1))
        return format(metres, 2);
    return format(metres, 1);
}

void Importer::shootToTheRight()
{
    if (m_level.pigs.empty() || std::any_of(m_level.pigs.begin(), m_level.pigs.end(),
                                            [&](const PigDef& pig) { return pig.x >= m_level.slingshot.x; }))
        return;
    const double slingshotX = m_level.slingshot.x;
    // "+ 0.0" turns a mirrored 0 (-0) into 0, so that no file reads "-0".
    const auto mirrored = [](double x)
    {
        return tidy(-x) + 0.0;
    };
    const auto turned = [](double degrees)
    {
        return cleanAngle(-degrees) + 0.0;
    };
    m_level.slingshot.x = mirrored(m_level.slingshot.x);
    for (PigDef& pig : m_level.pigs)
        pig.x = mirrored(pig.x);
    for (BlockDef& block : m_level.blocks)
    {
        block.x = mirrored(block.x);
        // A right triangle mirrored has its right angle at the bottom right: ours turned a quarter (its sides are
        // equal, as all of Science Birds' are).
        block.angleDeg = block.shape == BlockShape::Triangle ? cleanAngle(90.0 - block.angleDeg) + 0.0
                         : block.shape == BlockShape::Circle ? 0.0
                                                             : turned(block.angleDeg);
    }
    for (TerrainDef& terrain : m_level.terrain)
    {
        terrain.x = mirrored(terrain.x);
        terrain.angleDeg = turned(terrain.angleDeg);
    }
    m_warnings.push_back(issueAt(m_placeOf.count("/slingshot") ? m_placeOf["/slingshot"] : 0, "/slingshot",
                                 "the slingshot stands right of every pig (x = " + shortestNumber(slingshotX) +
                                     "): the scene is mirrored (every x becomes -x) so that it shoots to the right, "
                                     "as ours does"));
}

void Importer::useOwnGround()
{
    // The bodies on the ground or on nothing (not on a block or a platform): Science Birds' hand-made levels stand
    // them on a ground of their own, higher than its generator's -3.5. When the lowest of them all float the same
    // height above ours, more than the snap closes, that height is the file's ground.
    std::vector<double> gaps;
    for (std::size_t i = 0; i < m_level.blocks.size(); ++i)
        if (const SupportGap under = supportUnder(m_level, m_catalog, false, static_cast<int>(i));
            under.support.empty() || under.support == "the ground")
            gaps.push_back(bottomOf(m_level.blocks[i]) - m_level.groundY);
    for (std::size_t i = 0; i < m_level.pigs.size(); ++i)
        if (const SupportGap under = supportUnder(m_level, m_catalog, true, static_cast<int>(i));
            under.support.empty() || under.support == "the ground")
        {
            const PigType* type = m_catalog.findPig(m_level.pigs[i].type);
            gaps.push_back(m_level.pigs[i].y - (type ? type->radiusM : 0.25) - m_level.groundY);
        }
    // Bodies written inside the ground say nothing about where it is: Science Birds' ground pushes them out.
    gaps.erase(std::remove_if(gaps.begin(), gaps.end(), [](double gap) { return gap < -kScienceBirdsSnapM; }),
               gaps.end());
    if (gaps.empty())
        return;
    const double lift = tidy(*std::min_element(gaps.begin(), gaps.end()));
    if (lift <= kScienceBirdsSnapM)
        return;
    // A ground of its own holds everything above it: when some body stands lower (on a platform reaching down to
    // Science Birds' ground, as Phy-Q's levels do), the high ones stand on something the checks do not see as a
    // support, and the file's ground is Science Birds' own.
    double lowest = 1e300;
    const auto consider = [&](double bottom)
    {
        if (bottom >= -kScienceBirdsSnapM)
            lowest = std::min(lowest, bottom);
    };
    for (std::size_t i = 0; i < m_level.blocks.size(); ++i)
        consider(bottomOf(m_level.blocks[i]) - m_level.groundY);
    for (const PigDef& pig : m_level.pigs)
    {
        const PigType* type = m_catalog.findPig(pig.type);
        consider(pig.y - (type ? type->radiusM : 0.25) - m_level.groundY);
    }
    if (lift > lowest + kScienceBirdsSnapM)
        return;
    for (BlockDef& block : m_level.blocks)
        block.y = tidy(block.y - lift);
    for (PigDef& pig : m_level.pigs)
        pig.y = tidy(pig.y - lift);
    for (TerrainDef& terrain : m_level.terrain)
    {
        terrain.y = tidy(terrain.y - lift);
        for (auto& point : terrain.points)
            point.y = tidy(point.y - lift);
    }
    // The slingshot comes down with the scene, its pouch kept at least a metre above the ground.
    m_level.slingshot.y = std::max(1.0, tidy(m_level.slingshot.y - lift));
    m_warnings.push_back(issueAt(0, "",
                                 "its lowest bodies stand " + centimetres(lift) + " above Science Birds' ground (y = " +
                                     shortestNumber(kScienceBirdsGroundY) + "): read with a ground of its own at y = " +
                                     shortestNumber(tidy(kScienceBirdsGroundY + lift)) +
                                     ", so everything is that much lower than Science Birds' generator places it"));
}

void Importer::seatRoundBodies()
{
    for (const SeatedBody& body : seatRoundBodiesOnFlats(m_level, m_catalog, kScienceBirdsSnapM))
    {
        const double x = body.pig ? m_level.pigs[body.index].x : m_level.blocks[body.index].x;
        warnAt(body.pointer(), "its centre is " + centimetres(body.distanceM) + " past " + body.support +
                                   "'s edge, where Science Birds' " + (body.pig ? "pig" : "circle") +
                                   " stands on its flat bottom and ours, being round, rolls off; moved " +
                                   centimetres(body.dxM) + (body.dxM > 0 ? " right" : " left") +
                                   " onto it (x = " + shortestNumber(x) + " in our level)");
    }
}

void Importer::settleIntoGaps()
{
    for (const SeatedBody& body : settleRoundBodiesIntoGaps(m_level, m_catalog, kScienceBirdsSnapM))
    {
        const double x = body.pig ? m_level.pigs[body.index].x : m_level.blocks[body.index].x;
        const double y = body.pig ? m_level.pigs[body.index].y : m_level.blocks[body.index].y;
        warnAt(body.pointer(), "stands across the " + centimetres(body.distanceM) + " gap between " + body.support +
                                   ", where Science Birds' " + (body.pig ? "pig" : "circle") +
                                   " rests on its flat bottom and ours, being round, settles into it; set into it "
                                   "(x = " +
                                   shortestNumber(x) + ", y = " + shortestNumber(y) + " in our level)");
    }
}

void Importer::snapOntoSupports()
{
    // Science Birds builds a level a few centimetres apart and lets it fall into place; bodies that overlap or reach
    // below the ground its physics pushes out at once. Each body, bottom to top, goes onto what is under it where
    // that has ended up; whether it is close enough to be set there is judged by the gap in the file, so that gaps
    // stacked up a tower never add up.
    struct Body
    {
        bool pig;
        int index;
        double bottom;
    };
    const LevelDef asWritten = m_level;
    std::vector<Body> bodies;
    for (std::size_t i = 0; i < m_level.blocks.size(); ++i)
        bodies.push_back({false, static_cast<int>(i), bottomOf(m_level.blocks[i])});
    for (std::size_t i = 0; i < m_level.pigs.size(); ++i)
    {
        const PigType* type = m_catalog.findPig(m_level.pigs[i].type);
        bodies.push_back({true, static_cast<int>(i), m_level.pigs[i].y - (type ? type->radiusM : 0.25)});
    }
    std::stable_sort(bodies.begin(), bodies.end(), [](const Body& a, const Body& b) { return a.bottom < b.bottom; });
    for (const Body& body : bodies)
    {
        const std::string pointer = (body.pig ? "/pigs/" : "/blocks/") + std::to_string(body.index);
        const std::size_t offset = m_placeOf.count(pointer) ? m_placeOf[pointer] : 0;
        double& y = body.pig ? m_level.pigs[static_cast<std::size_t>(body.index)].y
                             : m_level.blocks[static_cast<std::size_t>(body.index)].y;
        if (body.bottom < m_level.groundY - 1e-6 &&
            supportUnder(asWritten, m_catalog, body.pig, body.index).support.empty())
        {
            // Deeper in the ground than a support is looked for: pushed up onto it, as Science Birds' ground does.
            const double below = m_level.groundY - body.bottom;
            y = tidy(y + below);
            m_warnings.push_back(issueAt(offset, pointer,
                                         "reaches " + centimetres(below) +
                                             " below the ground, which pushes it out in Science Birds; set onto the "
                                             "ground (y = " +
                                             shortestNumber(y) + " in our level)"));
            continue;
        }
        const SupportGap written = supportUnderFlatBottom(asWritten, m_catalog, body.pig, body.index);
        const SupportGap now = supportUnderFlatBottom(m_level, m_catalog, body.pig, body.index);
        if (now.support.empty() || std::abs(now.gapM) < 1e-6)
            continue;
        if (written.gapM > kScienceBirdsSnapM)
        {
            // Held up by something it overlaps (a pig on the pigs under it): pushApart sets it on them.
            if (deepestOverlap(m_level, m_catalog, body.pig, static_cast<std::size_t>(body.index)) >
                limits::kOverlapToleranceM / 2.0)
                continue;
            m_warnings.push_back(issueAt(offset, pointer,
                                         "is " + centimetres(written.gapM, kScienceBirdsSnapM) + " above " +
                                             written.support + ", more than the " + centimetres(kScienceBirdsSnapM) +
                                             " the import closes: left where it is (abalike check reports it)"));
            continue;
        }
        y = tidy(y - now.gapM);
        const double inFile = written.support.empty() ? now.gapM : written.gapM;
        if (std::abs(inFile) < 5e-4)
            continue; // it rested on its support in the file and came down with it: that one's warning says so
        std::string message = inFile > 0 ? "was " + centimetres(inFile) + " above " + now.support + "; set onto it"
                                         : "sank " + centimetres(inFile) + " into " + now.support +
                                               ", which Science Birds' physics pushes apart; set onto it";
        message.append(" (y = ").append(shortestNumber(y)).append(" in our level)");
        m_warnings.push_back(issueAt(offset, pointer, message));
    }
}

void Importer::pushApart()
{
    for (const PushedBody& body : pushApartOverlaps(m_level, m_catalog, limits::kOverlapToleranceM / 2.0))
    {
        const std::size_t offset = m_placeOf.count(body.pointer) ? m_placeOf[body.pointer] : 0;
        const bool lifted = body.dyM != 0.0;
        const bool pig = body.pointer.rfind("/pigs/", 0) == 0;
        const std::size_t index =
            static_cast<std::size_t>(std::stoul(body.pointer.substr(body.pointer.rfind('/') + 1)));
        const double x = pig ? m_level.pigs[index].x : m_level.blocks[index].x;
        const double y = pig ? m_level.pigs[index].y : m_level.blocks[index].y;
        m_warnings.push_back(
            issueAt(offset, body.pointer,
                    "overlapped " + body.other + " by " + centimetres(body.depthM) +
                        ", which Science Birds' physics pushes apart; " +
                        (lifted ? "lifted " + centimetres(body.dyM) + " (y = " + shortestNumber(y)
                                : "moved " + centimetres(body.dxM) + (body.dxM > 0 ? " right" : " left") +
                                      " (x = " + shortestNumber(x)) +
                        " in our level)"));
    }
}

void Importer::checkResult()
{
    const auto locate = [&](LevelIssue issue)
    {
        // The body an issue names: "/blocks/3/material" belongs to "/blocks/3".
        std::string pointer = issue.pointer;
        while (!pointer.empty() && m_placeOf.count(pointer) == 0)
            pointer.erase(pointer.rfind('/') == std::string::npos ? 0 : pointer.rfind('/'));
        const LevelIssue place =
            issueAt(pointer.empty() ? 0 : m_placeOf[pointer], issue.pointer, "in the imported level: " + issue.message);
        return place;
    };
    for (const LevelIssue& issue : checkLevelFields(m_level, m_catalog))
        m_errors.push_back(locate(issue));
    if (!m_errors.empty())
        return;
    for (const LevelIssue& issue : checkLevelGeometry(m_level, m_catalog))
        m_warnings.push_back(locate(issue));
}

ScienceBirdsLevel Importer::run(std::string_view bytes)
{
    XmlText text = decodeXmlBytes(bytes);
    if (!text.error.empty())
        throw LevelLoadError(
            {{m_file, 0, 0, "",
              text.error + " at byte " + std::to_string(text.errorOffset) + " (expected UTF-8 or UTF-16 text)"}});
    m_original = text.utf8;
    std::string repaired = text.utf8;
    m_closed = closeOpenLeafTags(repaired, {"Camera", "Slingshot", "Bird", "Block", "Pig", "TNT", "Platform"});
    for (const ClosedTag& tag : m_closed)
    {
        const TextPlace place = placeOf(m_original, tag.offset);
        m_warnings.push_back(
            {m_file, place.line, place.column, "",
             "<" + tag.name + "> is not closed; read as <" + tag.name + " .../> (as Science Birds does)"});
    }

    pugi::xml_document document;
    const pugi::xml_parse_result parsed =
        document.load_buffer(repaired.data(), repaired.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!parsed)
    {
        // A file that ends inside its elements (a lost "</GameObjects></Level>") still holds every object before.
        const bool endsOpen =
            repaired.find_first_not_of(" \t\n", static_cast<std::size_t>(parsed.offset)) == std::string::npos &&
            (parsed.status == pugi::status_end_element_mismatch || parsed.status == pugi::status_bad_end_element);
        if (!endsOpen || !document.child("Level"))
        {
            const LevelIssue issue = issueAt(static_cast<std::size_t>(parsed.offset), "",
                                             std::string("not well-formed XML: ") + parsed.description());
            throw LevelLoadError({issue});
        }
        m_warnings.push_back(issueAt(repaired.size(), "",
                                     "the file ends before its elements are closed; read "
                                     "everything it holds"));
    }
    const pugi::xml_node level = document.child("Level");
    if (!level)
        throw LevelLoadError({{m_file, 1, 1, "", "not a Science Birds level (expected a <Level> element)"}});

    std::string stem = std::filesystem::path(m_file).stem().string();
    std::string id;
    for (const char c : stem)
    {
        const char lower = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        const bool keep = (lower >= 'a' && lower <= 'z') || (lower >= '0' && lower <= '9');
        if (keep)
            id += lower;
        else if (!id.empty() && id.back() != '-')
            id += '-';
    }
    while (!id.empty() && id.back() == '-')
        id.pop_back();
    m_level.id = id.empty() ? "science-birds-level" : id;
    m_level.title = "Science Birds: " + (id.empty() ? std::string("level") : id);

    readBirds(level);
    readSlingshot(level);
    const pugi::xml_node objects = level.child("GameObjects");
    if (!objects)
        fail(level, "no <GameObjects> (expected the level's blocks and pigs in it)");
    else
        readObjects(objects);
    for (const pugi::xml_node node : level.children())
    {
        const std::string name = node.name();
        if (node.type() == pugi::node_element && name != "Birds" && name != "BirdsAmount" && name != "Slingshot" &&
            name != "GameObjects" && name != "Camera" && name != "Score")
            warn(node, "", "<" + name + "> is not part of a Science Birds level; left out");
    }
    if (m_options.sandbox)
        m_level.sandbox = true; // a structure without pigs, for the editor
    else if (m_errors.empty() && m_level.pigs.empty())
        fail(objects ? objects : level, "the file has no <Pig>, and a level without a pig cannot be won: import it "
                                        "with --sandbox to open the structure in the editor as a sandbox scene");
    if (m_squaredRotations > 0)
    {
        char most[32];
        std::snprintf(most, sizeof most, "%.2f", m_mostSquaredDeg);
        m_warnings.push_back(issueAt(0, "",
                                     std::to_string(m_squaredRotations) +
                                         " rotation(s) within 5 degrees of square read as square (the most by " + most +
                                         " degrees): Science Birds' generators write the angles a settled scene "
                                         "ended at, and ours starts square"));
    }
    if (m_errors.empty())
    {
        shootToTheRight();
        useOwnGround();
        seatRoundBodies();
        snapOntoSupports();
        settleIntoGaps();
        pushApart();
        checkResult();
    }
    if (!m_errors.empty())
        throw LevelLoadError(m_errors);
    std::stable_sort(m_warnings.begin(), m_warnings.end(),
                     [](const LevelIssue& a, const LevelIssue& b)
                     { return std::tie(a.line, a.column) < std::tie(b.line, b.column); });
    return {m_level, m_warnings};
}

} // namespace

ScienceBirdsLevel importScienceBirds(std::string_view bytes, const std::string& fileName, const Catalog& catalog,
                                     const ScienceBirdsOptions& options)
{
    return Importer(fileName, catalog, options).run(bytes);
}

} // namespace abalike
