#include "level/JsonLocator.hpp"
#include "level/JsonText.hpp"
#include "level/LevelReader.hpp"
#include "level/LevelSections.hpp"
#include <abalike/level/LevelLimits.hpp>

#include <abalike/level/LevelCatalog.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/level/PolygonPartition.hpp>
#include <abalike/level/SafeText.hpp>
#include <abalike/level/WorldTheme.hpp>
#include <abalike/teach/Claims.hpp>
#include <abalike/teach/TextValues.hpp>
#include <abalike/world/Catalog.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

namespace abalike
{

namespace
{

using json = nlohmann::json;
using namespace abalike::limits;

constexpr NumberRange kCoordinate{-kWorldExtentM, kWorldExtentM, "m", "outside the world"};
constexpr NumberRange kAngle{-kMaxAngleDeg, kMaxAngleDeg, "degrees"};
constexpr NumberRange kMovingSize{kMinBodySizeM, kMaxMovingSizeM, "m",
                                  "outside the sizes Box2D simulates well for a moving body"};
constexpr NumberRange kStaticSize{kMinBodySizeM, kMaxStaticSizeM, "m",
                                  "outside the sizes Box2D simulates well for a static body"};

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

void readBlocks(LevelReader& r, const json& root, LevelDef& level, const Catalog& catalog)
{
    const auto it = root.find("blocks");
    if (it == root.end() || !r.array(*it, "/blocks", 0, kMaxBlocks, "blocks"))
        return;
    const auto materials = names(catalog.materials());
    for (std::size_t i = 0; i < it->size(); ++i)
    {
        const json& b = (*it)[i];
        const std::string p = "/blocks/" + std::to_string(i);
        if (!r.object(b, p, {"shape", "material", "x", "y", "w", "h", "angle_deg", "wall"}))
            continue;
        BlockDef block;
        const std::string shape = r.string(b, p, "shape", "box", false);
        if (shape == "box")
            block.shape = BlockShape::Box;
        else if (shape == "circle")
            block.shape = BlockShape::Circle;
        else if (shape == "triangle")
            block.shape = BlockShape::Triangle;
        else if (shape == "hollow_box")
            block.shape = BlockShape::HollowBox;
        else
            checkName(r, p + "/shape", "shape", shape, {"box", "circle", "triangle", "hollow_box"});
        block.material = r.string(b, p, "material", "wood", true);
        checkName(r, p + "/material", "material", block.material, materials);
        block.x = r.number(b, p, "x", 0.0, true, kCoordinate);
        block.y = r.number(b, p, "y", 0.0, true, kCoordinate);
        block.widthM = r.number(b, p, "w", 1.0, true, kMovingSize);
        if (block.shape == BlockShape::Circle)
        {
            if (b.contains("h"))
                r.error(p + "/h", "a circle's only size is its diameter \"w\" (expected no \"h\", got " +
                                      describeJsonType(b["h"]) + ")");
            block.heightM = block.widthM;
        }
        else
            block.heightM = r.number(b, p, "h", 1.0, true, kMovingSize);
        block.angleDeg = r.number(b, p, "angle_deg", 0.0, false, kAngle);
        if (block.shape == BlockShape::HollowBox)
        {
            // Each wall is a Box2D polygon at least 5 cm thick, and the frame must leave a hole of 10 cm or more.
            const double maxWall = std::max(0.05, 0.5 * std::min(block.widthM, block.heightM) - 0.05);
            block.wallM =
                r.number(b, p, "wall", 0.1, false, NumberRange{0.05, maxWall, "m", "does not leave a hollow"});
        }
        else if (b.contains("wall"))
            r.error(p + "/wall", "only a \"hollow_box\" has a wall thickness (got shape \"" + shape + "\")");
        level.blocks.push_back(block);
    }
}

void readPigs(LevelReader& r, const json& root, LevelDef& level, const Catalog& catalog)
{
    const auto it = root.find("pigs");
    if (it == root.end())
    {
        if (!level.sandbox)
            r.error("", "missing required key \"pigs\" (expected an array with at least one pig, or \"sandbox\": "
                        "true for a scene without pigs)");
        return;
    }
    if (it->is_array() && it->empty() && !level.sandbox)
    {
        r.error("/pigs", "wrong number of pigs (expected 1 to " + std::to_string(kMaxPigs) +
                             ", got 0); only a \"sandbox\": true scene may have no pig");
        return;
    }
    if (!r.array(*it, "/pigs", level.sandbox ? 0 : 1, kMaxPigs, "pigs"))
        return;
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
        pig.x = r.number(g, p, "x", 0.0, true, kCoordinate);
        pig.y = r.number(g, p, "y", 0.0, true, kCoordinate);
        level.pigs.push_back(pig);
    }
}

/// A terrain polygon: "points": [[x, y], ...], simple, 3 to kMaxTerrainPoints corners, no wider or taller than a
/// static body may be; its box fields then hold the bounding box.
std::optional<TerrainDef> readTerrainPolygon(LevelReader& r, const json& t, const std::string& p)
{
    for (const char* key : {"x", "y", "w", "h", "angle_deg"})
        if (t.contains(key))
        {
            r.error(p + "/" + key, std::string("a polygon's shape is its \"points\" (expected no \"") + key +
                                       "\"; give either points or x, y, w and h)");
            return std::nullopt;
        }
    const json& points = t.at("points");
    const std::string pp = p + "/points";
    if (!r.array(points, pp, 3, kMaxTerrainPoints, "points"))
        return std::nullopt;
    TerrainDef terrain;
    bool ok = true;
    for (std::size_t k = 0; k < points.size(); ++k)
    {
        const std::string at = pp + "/" + std::to_string(k);
        if (!points[k].is_array() || points[k].size() != 2)
        {
            r.error(at, "expected a point [x, y] in metres, got " + describeJsonType(points[k]) +
                            (points[k].is_array() ? " of " + std::to_string(points[k].size()) + " numbers" : ""));
            ok = false;
            continue;
        }
        const std::optional<double> x = r.numberAt(points[k][0], at + "/0", kCoordinate);
        const std::optional<double> y = r.numberAt(points[k][1], at + "/1", kCoordinate);
        if (!x || !y)
        {
            ok = false;
            continue;
        }
        terrain.points.push_back({*x, *y});
    }
    if (!ok)
        return std::nullopt;
    double left = terrain.points[0].x, right = left, bottom = terrain.points[0].y, top = bottom;
    for (const auto& [x, y] : terrain.points)
    {
        left = std::min(left, x);
        right = std::max(right, x);
        bottom = std::min(bottom, y);
        top = std::max(top, y);
    }
    // A polygon whose points all lie on one line has no area (and "crosses itself" along that line): say the
    // former. Otherwise a crossing is the problem to fix first.
    const bool tiny = std::abs(twiceSignedArea(terrain.points)) < 2.0 * kMinBodySizeM * kMinBodySizeM;
    bool onOneLine = true;
    for (const auto& point : terrain.points)
    {
        const auto& a = terrain.points.front();
        const auto& b = terrain.points[terrain.points.size() / 2];
        onOneLine = onOneLine && std::abs((b.x - a.x) * (point.y - a.y) - (b.y - a.y) * (point.x - a.x)) < 1e-9;
    }
    if (tiny && onOneLine)
    {
        r.error(pp, "the polygon has (almost) no area (expected at least 0.01 m^2: are its points on one line?)");
        return std::nullopt;
    }
    if (const std::optional<EdgeCrossing> crossing = firstCrossing(terrain.points))
    {
        const std::size_t n = terrain.points.size();
        r.error(pp, "the outline crosses itself: the edge from point " + std::to_string(crossing->first) + " to " +
                        std::to_string((crossing->first + 1) % n) + " meets the edge from point " +
                        std::to_string(crossing->second) + " to " + std::to_string((crossing->second + 1) % n) +
                        " (expected a simple polygon: list the corners in order around it)");
        return std::nullopt;
    }
    if (tiny)
    {
        r.error(pp, "the polygon has (almost) no area (expected at least 0.01 m^2: are its points on one line?)");
        return std::nullopt;
    }
    if (right - left > kMaxStaticSizeM || top - bottom > kMaxStaticSizeM)
    {
        std::ostringstream why;
        why << "the polygon is " << right - left << " x " << top - bottom << " m (expected at most " << kMaxStaticSizeM
            << " m each way, the largest static body Box2D simulates well: split it into pieces)";
        r.error(pp, why.str());
        return std::nullopt;
    }
    terrain.x = 0.5 * (left + right);
    terrain.y = 0.5 * (bottom + top);
    terrain.widthM = right - left;
    terrain.heightM = top - bottom;
    return terrain;
}

void readTerrain(LevelReader& r, const json& root, LevelDef& level)
{
    const auto it = root.find("terrain");
    if (it == root.end() || !r.array(*it, "/terrain", 0, kMaxTerrain, "terrain pieces"))
        return;
    for (std::size_t i = 0; i < it->size(); ++i)
    {
        const json& t = (*it)[i];
        const std::string p = "/terrain/" + std::to_string(i);
        if (!r.object(t, p, {"x", "y", "w", "h", "angle_deg", "points"}))
            continue;
        if (t.contains("points"))
        {
            if (std::optional<TerrainDef> polygon = readTerrainPolygon(r, t, p))
                level.terrain.push_back(std::move(*polygon));
            continue;
        }
        TerrainDef terrain;
        terrain.x = r.number(t, p, "x", 0.0, true, kCoordinate);
        terrain.y = r.number(t, p, "y", 0.0, true, kCoordinate);
        terrain.widthM = r.number(t, p, "w", 1.0, true, kStaticSize);
        terrain.heightM = r.number(t, p, "h", 1.0, true, kStaticSize);
        terrain.angleDeg = r.number(t, p, "angle_deg", 0.0, false, kAngle);
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
    if (!r.array(*it, "/birds", 1, kMaxBirds, "birds"))
        return;
    auto birdTypes = names(catalog.birds());
    birdTypes.push_back(kCustomBirdName);
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
        if (name == kCustomBirdName && !root.contains("custom_bird"))
            r.error(p, "the level defines no custom bird (expected a \"custom_bird\" object with \"mass_kg\", "
                       "\"diameter_m\" and \"drag_coefficient\")");
        level.birds.push_back(name);
    }
}

/// An optional number of the slingshot: absent leaves the catalog's.
std::optional<double> ownBandNumber(LevelReader& r, const json& sling, const char* key, const NumberRange& range)
{
    const auto it = sling.find(key);
    if (it == sling.end())
        return std::nullopt;
    return r.numberAt(*it, std::string("/slingshot/") + key, range);
}

void readSlingshot(LevelReader& r, const json& root, LevelDef& level)
{
    const auto sling = root.find("slingshot");
    if (sling == root.end())
        r.error("", "missing required key \"slingshot\" (expected {\"x\", \"y\"})");
    else if (r.object(*sling, "/slingshot", {"x", "y", "max_force_n", "max_pull_m", "band_mass_kg"}))
    {
        level.slingshot.x = r.number(*sling, "/slingshot", "x", 0.0, true, kCoordinate);
        level.slingshot.y = r.number(*sling, "/slingshot", "y", 1.5, true, kCoordinate);
        level.slingshot.maxForceN = ownBandNumber(r, *sling, "max_force_n", NumberRange{kMinForceN, kMaxForceN, "N"});
        level.slingshot.maxPullM = ownBandNumber(r, *sling, "max_pull_m", NumberRange{kMinPullM, kMaxPullM, "m"});
        level.slingshot.bandMassKg = ownBandNumber(r, *sling, "band_mass_kg", NumberRange{0.0, kMaxBandMassKg, "kg"});
    }
}

void readStars(LevelReader& r, const json& root, LevelDef& level)
{
    const auto it = root.find("stars");
    if (it == root.end() || !r.array(*it, "/stars", 3, 3, "star scores [one, two, three]"))
        return;
    for (std::size_t i = 0; i < 3; ++i)
    {
        const json& v = (*it)[i];
        const std::string p = "/stars/" + std::to_string(i);
        const auto score = r.numberAt(v, p, NumberRange{0.0, static_cast<double>(kMaxStarScore), "points"});
        if (!score)
            return;
        if (*score != std::floor(*score))
        {
            r.error(p, "expected a whole score, got " + describeJsonType(v));
            return;
        }
        level.starScores[i] = static_cast<int>(*score);
    }
    if (!(level.starScores[0] <= level.starScores[1] && level.starScores[1] <= level.starScores[2]))
    {
        std::ostringstream message;
        message << "star scores must not decrease (expected one <= two <= three, got " << level.starScores[0] << ", "
                << level.starScores[1] << ", " << level.starScores[2] << ")";
        r.error("/stars", message.str());
    }
}

void readHints(LevelReader& r, const json& root, LevelDef& level)
{
    const auto it = root.find("hints");
    if (it == root.end() || !r.array(*it, "/hints", 0, kMaxHints, "hints"))
        return;
    for (std::size_t i = 0; i < it->size(); ++i)
    {
        if ((*it)[i].is_string())
            level.hints.push_back((*it)[i].get<std::string>());
        else
            r.error("/hints/" + std::to_string(i), "expected a string, got " + describeJsonType((*it)[i]));
    }
}

/// [min, max] of two numbers in range, min <= max; nullopt (reported) otherwise.
std::optional<std::array<double, 2>> readRange(LevelReader& r, const json& object, const std::string& p,
                                               const char* key, const NumberRange& range)
{
    const auto it = object.find(key);
    const std::string pointer = p + "/" + key;
    if (it == object.end() || !r.array(*it, pointer, 2, 2, "numbers [min, max]"))
        return std::nullopt;
    const auto low = r.numberAt((*it)[0], pointer + "/0", range);
    const auto high = r.numberAt((*it)[1], pointer + "/1", range);
    if (!low || !high)
        return std::nullopt;
    if (*low > *high)
    {
        r.error(pointer, "expected [min, max] with min <= max, got " + it->dump());
        return std::nullopt;
    }
    return std::array<double, 2>{*low, *high};
}

/// "outcome": {"shot": [ANGLE, SPEED], "pig_x": [MIN, MAX], "by_block_x": [MIN, MAX], "in_at_least": K}.
std::optional<OutcomeClaimDef> readOutcome(LevelReader& r, const json& value, const std::string& p,
                                           const Catalog& catalog)
{
    if (!r.object(value, p, {"shot", "pig_x", "by_block_x", "in_at_least"}))
        return std::nullopt;
    OutcomeClaimDef outcome;
    const auto shot = value.find("shot");
    if (shot == value.end())
        r.error(p, "missing required key \"shot\" (expected [angle_deg, speed_mps], the shot the text describes)");
    else if (r.array(*shot, p + "/shot", 2, 2, "numbers [angle_deg, speed_mps]"))
    {
        outcome.angleDeg = r.numberAt((*shot)[0], p + "/shot/0", NumberRange{-90.0, 90.0, "degrees"}).value_or(0.0);
        outcome.speedMps =
            r.numberAt((*shot)[1], p + "/shot/1", NumberRange{0.0, catalog.maxLaunchSpeedMps(), "m/s"}).value_or(0.0);
    }
    const NumberRange world{-kWorldExtentM, kWorldExtentM, "m"};
    if (value.find("pig_x") == value.end())
        r.error(p, "missing required key \"pig_x\" (expected [min, max]: where the pig the text promises stands)");
    else if (const auto pigX = readRange(r, value, p, "pig_x", world))
        outcome.pigX = *pigX;
    if (value.find("by_block_x") != value.end())
        outcome.byBlockX = readRange(r, value, p, "by_block_x", world);
    outcome.inAtLeast = static_cast<int>(
        r.number(value, p, "in_at_least", 1.0, true, NumberRange{1.0, static_cast<double>(kOutcomeFanAims), "aims"}));
    if (const auto k = value.find("in_at_least"); k != value.end() && k->is_number() && !k->is_number_integer() &&
                                                  k->get<double>() != std::floor(k->get<double>()))
        r.error(p + "/in_at_least", "expected a whole number of aims, got " + k->dump());
    return outcome;
}

/// "cannot_break": {"material": NAME, "cause": "bird"}.
std::optional<CannotBreakClaimDef> readCannotBreak(LevelReader& r, const json& value, const std::string& p,
                                                   const Catalog& catalog)
{
    if (!r.object(value, p, {"material", "cause"}))
        return std::nullopt;
    CannotBreakClaimDef claim;
    claim.material = r.string(value, p, "material", "", true);
    if (!claim.material.empty() && catalog.findMaterial(claim.material) == nullptr)
    {
        std::vector<std::string> names;
        for (const Material& material : catalog.materials())
            names.push_back(material.name);
        const auto guess = closestMatch(claim.material, names);
        r.error(p + "/material", "unknown material \"" + claim.material + "\"" +
                                     (guess ? " (did you mean \"" + *guess + "\"?)" : std::string()));
    }
    const std::string cause = r.string(value, p, "cause", "any", false);
    if (cause != "any" && cause != "bird")
        r.error(p + "/cause", "expected \"bird\" (only the bird's own hit counts) or \"any\", got \"" + cause + "\"");
    claim.byBirdOnly = cause == "bird";
    return claim;
}

/// "full_pull_reach": {"pig_x": [MIN, MAX], "within_deg": D}.
std::optional<ReachClaimDef> readReach(LevelReader& r, const json& value, const std::string& p)
{
    if (!r.object(value, p, {"pig_x", "within_deg"}))
        return std::nullopt;
    ReachClaimDef reach;
    if (value.find("pig_x") == value.end())
        r.error(p, "missing required key \"pig_x\" (expected [min, max]: where the pig the text promises stands)");
    else if (const auto pigX = readRange(r, value, p, "pig_x", NumberRange{-kWorldExtentM, kWorldExtentM, "m"}))
        reach.pigX = *pigX;
    reach.withinDeg = r.number(value, p, "within_deg", 0.0, true, NumberRange{0.5, 45.0, "degrees"});
    return reach;
}

void readClaims(LevelReader& r, const json& root, LevelDef& level, const Catalog& catalog)
{
    const auto it = root.find("claims");
    if (it == root.end() || !r.array(*it, "/claims", 0, kMaxClaims, "claims"))
        return;
    for (std::size_t i = 0; i < it->size(); ++i)
    {
        const std::string p = "/claims/" + std::to_string(i);
        const json& item = (*it)[i];
        if (!r.object(item, p, {"about", "holds", "outcome", "cannot_break", "full_pull_reach"}))
            continue;
        ClaimDef claim;
        claim.about = r.string(item, p, "about", "", true);
        const bool holds = item.contains("holds");
        const bool outcome = item.contains("outcome");
        const bool cannotBreak = item.contains("cannot_break");
        const bool reach = item.contains("full_pull_reach");
        const int forms = (holds ? 1 : 0) + (outcome ? 1 : 0) + (cannotBreak ? 1 : 0) + (reach ? 1 : 0);
        if (forms != 1)
            r.error(p, forms > 1 ? "expected one of \"holds\", \"outcome\", \"cannot_break\" and "
                                   "\"full_pull_reach\", not several"
                                 : "missing \"holds\" (a comparison), \"outcome\" (what a shot does), "
                                   "\"cannot_break\" (a material no shot breaks) or \"full_pull_reach\" (the "
                                   "angles that reach a pig at full pull)");
        if (holds)
            claim.holds = r.string(item, p, "holds", "", true);
        else if (outcome)
            claim.outcome = readOutcome(r, item["outcome"], p + "/outcome", catalog);
        else if (cannotBreak)
            claim.cannotBreak = readCannotBreak(r, item["cannot_break"], p + "/cannot_break", catalog);
        else if (reach)
            claim.reach = readReach(r, item["full_pull_reach"], p + "/full_pull_reach");
        level.claims.push_back(std::move(claim));
    }
}

/// A claim backs a text the level has, and its comparison names values this level has (levels/README.md).
void checkClaims(LevelReader& r, const LevelDef& level, const Catalog& catalog)
{
    for (std::size_t i = 0; i < level.claims.size(); ++i)
    {
        const ClaimDef& claim = level.claims[i];
        const std::string p = "/claims/" + std::to_string(i);
        bool known = claim.about == "/concept" && !level.lesson.empty();
        for (std::size_t h = 0; h < level.hints.size() && !known; ++h)
            known = claim.about == "/hints/" + std::to_string(h);
        if (!known)
        {
            const std::size_t hints = level.hints.size();
            const std::string texts =
                hints == 0   ? "\"/concept\" (the level has no hints)"
                : hints == 1 ? "\"/concept\" or \"/hints/0\""
                             : "\"/concept\" or \"/hints/0\" to \"/hints/" + std::to_string(hints - 1) + "\"";
            r.error(p + "/about", "expected the text the claim backs: " + texts + ", got \"" + claim.about + "\"");
        }
        if (!claim.outcome && !claim.cannotBreak && !claim.reach && !claim.holds.empty())
            for (const auto& [offset, message] : checkClaim(claim.holds, level, catalog))
                r.error(p + "/holds", "character " + std::to_string(offset + 1) + " of the claim: " + message);
    }
}

/// The {...} placeholders of the concept and the hints name values this level has (docs: levels/README.md).
void checkTextPlaceholders(LevelReader& r, const LevelDef& level, const Catalog& catalog)
{
    const auto check = [&](const std::string& text, const std::string& pointer)
    {
        for (const TextValueError& e : checkText(text, level, catalog))
            r.error(pointer, "character " + std::to_string(e.offset() + 1) + " of the text: " + e.what());
    };
    check(level.lesson, "/concept");
    for (std::size_t i = 0; i < level.hints.size(); ++i)
        check(level.hints[i], "/hints/" + std::to_string(i));
}

void readReferenceShot(LevelReader& r, const json& root, LevelDef& level, const Catalog& catalog)
{
    const auto it = root.find("reference_shot");
    if (it == root.end() || !r.array(*it, "/reference_shot", 2, 2, "numbers [angle_deg, speed_mps]"))
        return;
    const auto angle = r.numberAt((*it)[0], "/reference_shot/0", NumberRange{-90.0, 90.0, "degrees"});
    const auto speed = r.numberAt((*it)[1], "/reference_shot/1", NumberRange{0.0, catalog.maxLaunchSpeedMps(), "m/s"});
    if (angle && speed)
        level.referenceShot = ReferenceShotDef{*angle, *speed};
}

/// A string field that must not be empty.
std::string nonEmptyString(LevelReader& r, const json& root, const char* key, bool required)
{
    std::string value = r.string(root, "", key, "", required);
    if (root.contains(key) && root[key].is_string() && value.empty())
        r.error(std::string("/") + key, "expected a non-empty string, got \"\"");
    return value;
}

void readHeader(LevelReader& r, const json& root, LevelDef& level)
{
    if (const auto format = root.find("format"); format == root.end())
        r.error("", "missing required key \"format\" (expected 1, the version of the level format)");
    else if (const auto version = r.numberAt(*format, "/format", NumberRange{0.0, 1.0e9}); version && *version != 1.0)
        r.error("/format", "unsupported format version (expected 1, got " + format->dump() + ")");
    if (const auto schema = root.find("$schema"); schema != root.end() && !schema->is_string())
        r.error("/$schema", "expected the path of the level schema as a string, got " + describeJsonType(*schema));
    level.id = nonEmptyString(r, root, "id", true);
    level.title = nonEmptyString(r, root, "title", true);
    level.episode = nonEmptyString(r, root, "episode", false);
    level.lesson = r.string(root, "", "concept", "", false);
    if (const auto sandbox = root.find("sandbox"); sandbox != root.end())
    {
        if (sandbox->is_boolean())
            level.sandbox = sandbox->get<bool>();
        else
            r.error("/sandbox", "expected true (a sandbox scene, which may have no pig) or false, got " +
                                    describeJsonType(*sandbox));
    }
    if (root.contains("time_limit_s"))
        level.timeLimitS =
            r.number(root, "", "time_limit_s", 0.0, true, NumberRange{kMinTimeLimitS, kMaxTimeLimitS, "s"});
    if (const auto theme = root.find("theme"); theme != root.end())
    {
        const std::optional<WorldTheme> named =
            theme->is_string() ? parseWorldTheme(theme->get<std::string>()) : std::nullopt;
        if (named)
            level.theme = named;
        else
            r.error("/theme", "expected the world the scenery shows: \"earth\", \"moon\", \"mars\", \"titan\" or "
                              "\"jupiter\", got " +
                                  theme->dump());
    }
    if (const auto ground = root.find("ground"); ground != root.end() && r.object(*ground, "/ground", {"y"}))
        level.groundY = r.number(*ground, "/ground", "y", 0.0, false, kCoordinate);
}

} // namespace

std::string LevelIssue::format() const
{
    // File names, keys and names echoed in messages come from anyone's files: escape what would act on a terminal.
    std::ostringstream out;
    out << escapeForTerminal(file) << ':' << line << ':' << column
        << ": error: " << escapeForTerminal(pointer.empty() ? "/" : pointer) << ": " << escapeForTerminal(message);
    return out.str();
}

LevelLoadError::LevelLoadError(std::vector<LevelIssue> issues)
    : std::runtime_error(issues.empty() ? std::string("invalid level") : issues.front().format()),
      m_issues(std::move(issues))
{
}

namespace
{

/// What parsing does with the geometry checks.
enum class Geometry
{
    Errors,   ///< they are errors like any other (loadLevel)
    Returned, ///< they go into the caller's list (the editor)
    Skipped,  ///< not run (checking the values alone)
};

LevelDef parseLevelText(std::string_view text, const std::string& fileName, const Catalog& catalog,
                        Geometry geometryMode, std::vector<LevelIssue>* geometryIssues = nullptr)
{
    const json root = parseJsonText(text, fileName, kLevelText);
    const JsonLocator locator(text);
    LevelReader r(fileName, locator);
    r.duplicateKeys();
    r.safeText(root);
    LevelDef level;
    level.sourcePath = fileName;
    if (!r.object(root, "", {"$schema",      "format",         "id",      "title",       "episode",   "concept",
                             "hints",        "sandbox",        "ground",  "slingshot",   "birds",     "custom_bird",
                             "blocks",       "pigs",           "terrain", "environment", "materials", "stars",
                             "time_limit_s", "reference_shot", "theme",   "claims"}))
        throw LevelLoadError(r.take());

    readHeader(r, root, level);
    readHints(r, root, level);
    readClaims(r, root, level, catalog);
    readSlingshot(r, root, level);
    readBirds(r, root, level, catalog);
    readBlocks(r, root, level, catalog);
    readPigs(r, root, level, catalog);
    readTerrain(r, root, level);
    readEnvironment(r, root, level);
    readMaterialOverrides(r, root, level, catalog);
    readCustomBird(r, root, level);
    readStars(r, root, level);
    readReferenceShot(r, root, level, catalog);
    if (r.ok())
    {
        checkTextPlaceholders(r, level, catalog);
        checkClaims(r, level, catalog);
    }
    if (!r.ok())
        throw LevelLoadError(r.take());

    // Geometry and reach only mean something once every field read cleanly; a fallback value would only add
    // confusing follow-on errors.
    if (geometryMode == Geometry::Skipped)
        return level;
    LevelReader geometry(fileName, locator);
    checkLevel(level, levelCatalog(level, catalog), geometry);
    if (geometryMode == Geometry::Returned)
        *geometryIssues = geometry.take();
    else if (!geometry.ok())
        throw LevelLoadError(geometry.take());
    return level;
}

} // namespace

LevelDef parseLevel(std::string_view text, const std::string& fileName, const Catalog& catalog)
{
    return parseLevelText(text, fileName, catalog, Geometry::Errors);
}

EditableLevel parseLevelForEditing(std::string_view text, const std::string& fileName, const Catalog& catalog)
{
    EditableLevel out;
    out.level = parseLevelText(text, fileName, catalog, Geometry::Returned, &out.geometryIssues);
    return out;
}

EditableLevel loadLevelForEditing(const std::string& path, const Catalog& catalog)
{
    return parseLevelForEditing(readJsonFile(path, kLevelText), path, catalog);
}

std::vector<LevelIssue> checkLevelFields(const LevelDef& level, const Catalog& catalog)
{
    // The same text the level would be saved as, read back by the same reader: one definition of what is valid.
    try
    {
        parseLevelText(writeLevelJson(level, "schema/level.schema.json"), level.sourcePath, catalog, Geometry::Skipped);
    }
    catch (const LevelLoadError& e)
    {
        std::vector<LevelIssue> issues = e.issues();
        for (LevelIssue& issue : issues)
            issue.line = issue.column = 0;
        return issues;
    }
    return {};
}

std::vector<LevelIssue> checkLevelGeometry(const LevelDef& level, const Catalog& catalog)
{
    const JsonLocator locator("null");
    LevelReader r(level.sourcePath, locator);
    checkLevel(level, levelCatalog(level, catalog), r);
    std::vector<LevelIssue> issues = r.take();
    for (LevelIssue& issue : issues)
        issue.line = issue.column = 0; // a level in memory has no place in a file
    return issues;
}

std::vector<std::string> levelFilesIn(const std::string& folder)
{
    std::vector<std::string> files;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error))
        if (entry.path().extension() == ".json")
            files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

LevelDef loadLevel(const std::string& path, const Catalog& catalog)
{
    return parseLevel(readJsonFile(path, kLevelText), path, catalog);
}

} // namespace abalike
