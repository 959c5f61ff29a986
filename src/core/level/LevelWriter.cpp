#include <abalike/level/LevelWriter.hpp>
#include <abalike/level/WorldTheme.hpp>
#include <abalike/save/AtomicWrite.hpp>

#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

namespace abalike
{

namespace
{

/// Keys in the order they are set: the file lists them as the format documents them.
using OrderedJson = nlohmann::ordered_json;

/// Lines longer than this are broken up, one item per line.
constexpr std::size_t kLineWidth = 120;
/// Phases are stored in radians; written in degrees to 12 significant digits, so degrees -> radians -> degrees
/// gives back the digits written (90, not 90.00000000000001) and a second save the same bytes.
constexpr int kPhaseDigits = 12;

std::string number(double value)
{
    return shortestNumber(value);
}

std::string text(const std::string& value)
{
    return OrderedJson(value).dump(-1, ' ', false, OrderedJson::error_handler_t::replace);
}

/// A number whose text is already decided. It rides in the tree as a binary node, a type a level never has, so
/// the printer can tell it from a string and write it as it is.
OrderedJson raw(std::string text)
{
    return OrderedJson::binary_t(std::vector<std::uint8_t>(text.begin(), text.end()));
}

OrderedJson num(double value)
{
    return raw(number(value));
}

std::string inlineForm(const OrderedJson& value);

std::string scalar(const OrderedJson& value)
{
    if (value.is_binary())
    {
        const auto& bytes = value.get_binary();
        return std::string(bytes.begin(), bytes.end());
    }
    if (value.is_string())
        return text(value.get<std::string>());
    return value.dump();
}

std::string inlineForm(const OrderedJson& value)
{
    if (value.is_object())
    {
        std::string out = "{";
        bool first = true;
        for (const auto& [key, item] : value.items())
        {
            out += (first ? "" : ", ") + text(key) + ": " + inlineForm(item);
            first = false;
        }
        return out + "}";
    }
    if (value.is_array())
    {
        std::string out = "[";
        for (std::size_t i = 0; i < value.size(); ++i)
            out += (i ? ", " : "") + inlineForm(value[i]);
        return out + "]";
    }
    return scalar(value);
}

/// Writes value at the given indentation: inline when it fits the line, else one item per line. expand forces the
/// one-item-per-line form for this value (not its items).
void print(std::string& out, const OrderedJson& value, std::size_t indent, std::size_t column, bool expand)
{
    const bool container = value.is_object() || value.is_array();
    if (!container || value.empty())
    {
        out += container ? (value.is_object() ? "{}" : "[]") : scalar(value);
        return;
    }
    const std::string flat = inlineForm(value);
    if (!expand && column + flat.size() + 1 <= kLineWidth)
    {
        out += flat;
        return;
    }
    const std::string pad(indent + 2, ' ');
    out += value.is_object() ? "{\n" : "[\n";
    std::size_t i = 0;
    for (const auto& [key, item] : value.items())
    {
        out += pad;
        std::size_t itemColumn = pad.size();
        if (value.is_object())
        {
            out += text(key) + ": ";
            itemColumn += text(key).size() + 2;
        }
        print(out, item, indent + 2, itemColumn, false);
        out += ++i < value.size() ? ",\n" : "\n";
    }
    out += std::string(indent, ' ') + (value.is_object() ? "}" : "]");
}

OrderedJson blockJson(const BlockDef& b)
{
    const BlockDef defaults;
    OrderedJson out = OrderedJson::object();
    if (b.shape != BlockShape::Box)
        out["shape"] = blockShapeName(b.shape);
    out["material"] = b.material;
    out["x"] = num(b.x);
    out["y"] = num(b.y);
    out["w"] = num(b.widthM);
    if (b.shape != BlockShape::Circle)
        out["h"] = num(b.heightM);
    if (b.angleDeg != 0.0)
        out["angle_deg"] = num(b.angleDeg);
    if (b.shape == BlockShape::HollowBox && b.wallM != defaults.wallM)
        out["wall"] = num(b.wallM);
    return out;
}

OrderedJson environmentJson(const EnvironmentDef& e)
{
    const EnvironmentDef defaults;
    OrderedJson out = OrderedJson::object();
    if (e.gravity != defaults.gravity)
        out["gravity"] = num(e.gravity);
    if (e.airDensity != defaults.airDensity)
        out["air_density"] = num(e.airDensity);
    if (e.windX != 0.0 || e.windY != 0.0)
        out["wind"] = OrderedJson::array({num(e.windX), num(e.windY)});
    if (e.gusts && e.gusts->kind == GustDef::Kind::Steps)
    {
        OrderedJson steps = OrderedJson::array();
        for (const GustDef::Step& step : e.gusts->steps)
            steps.push_back({{"t", num(step.startS)}, {"wx", num(step.windX)}, {"wy", num(step.windY)}});
        out["gusts"] = std::move(steps);
    }
    else if (e.gusts)
    {
        OrderedJson sine = OrderedJson::object();
        sine["amplitude"] = OrderedJson::array({num(e.gusts->amplitudeX), num(e.gusts->amplitudeY)});
        sine["period_s"] = num(e.gusts->periodS);
        if (e.gusts->phaseRad != 0.0)
        {
            char buffer[64];
            const double degrees = e.gusts->phaseRad * 180.0 / std::numbers::pi;
            const auto result =
                std::to_chars(buffer, buffer + sizeof buffer, degrees, std::chars_format::general, kPhaseDigits);
            // Read back and print shortest, so trailing zeros and the exponent form match number().
            double rounded = degrees;
            std::from_chars(buffer, result.ptr, rounded);
            sine["phase_deg"] = num(rounded);
        }
        out["gusts"] = std::move(sine);
    }
    return out;
}

OrderedJson materialsJson(const std::vector<MaterialOverrideDef>& materials)
{
    OrderedJson out = OrderedJson::object();
    for (const MaterialOverrideDef& m : materials)
    {
        OrderedJson item = OrderedJson::object();
        if (m.densityKgPerM3)
            item["density_kg_per_m3"] = num(*m.densityKgPerM3);
        if (m.friction)
            item["friction"] = num(*m.friction);
        if (m.restitution)
            item["restitution"] = num(*m.restitution);
        if (m.strengthNs)
            item["strength_ns"] = num(*m.strengthNs);
        out[m.material] = std::move(item);
    }
    return out;
}

} // namespace

const char* blockShapeName(BlockShape shape)
{
    switch (shape)
    {
    case BlockShape::Circle:
        return "circle";
    case BlockShape::Triangle:
        return "triangle";
    case BlockShape::HollowBox:
        return "hollow_box";
    case BlockShape::Box:
        break;
    }
    return "box";
}

std::string shortestNumber(double value)
{
    if (value == 0.0)
        return "0"; // also -0
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string writeLevelJson(const LevelDef& level, const std::string& schemaReference)
{
    const LevelDef defaults;
    OrderedJson root = OrderedJson::object();
    if (!schemaReference.empty())
        root["$schema"] = schemaReference;
    root["format"] = level.format;
    root["id"] = level.id;
    root["title"] = level.title;
    if (!level.episode.empty())
        root["episode"] = level.episode;
    if (!level.lesson.empty())
        root["concept"] = level.lesson;
    if (!level.hints.empty())
        root["hints"] = level.hints;
    if (!level.claims.empty())
    {
        OrderedJson claims = OrderedJson::array();
        for (const ClaimDef& claim : level.claims)
        {
            if (claim.cannotBreak)
            {
                OrderedJson form = {{"material", claim.cannotBreak->material}};
                if (claim.cannotBreak->byBirdOnly)
                    form["cause"] = "bird";
                claims.push_back({{"about", claim.about}, {"cannot_break", std::move(form)}});
                continue;
            }
            if (claim.reach)
            {
                claims.push_back(
                    {{"about", claim.about},
                     {"full_pull_reach",
                      {{"pig_x", OrderedJson::array({num(claim.reach->pigX[0]), num(claim.reach->pigX[1])})},
                       {"within_deg", num(claim.reach->withinDeg)}}}});
                continue;
            }
            if (!claim.outcome)
            {
                claims.push_back({{"about", claim.about}, {"holds", claim.holds}});
                continue;
            }
            const OutcomeClaimDef& o = *claim.outcome;
            OrderedJson outcome = {{"shot", OrderedJson::array({num(o.angleDeg), num(o.speedMps)})},
                                   {"pig_x", OrderedJson::array({num(o.pigX[0]), num(o.pigX[1])})}};
            if (o.byBlockX)
                outcome["by_block_x"] = OrderedJson::array({num((*o.byBlockX)[0]), num((*o.byBlockX)[1])});
            outcome["in_at_least"] = o.inAtLeast;
            claims.push_back({{"about", claim.about}, {"outcome", std::move(outcome)}});
        }
        root["claims"] = std::move(claims);
    }
    if (level.sandbox)
        root["sandbox"] = true;
    if (level.groundY != 0.0)
        root["ground"] = {{"y", num(level.groundY)}};
    OrderedJson sling = {{"x", num(level.slingshot.x)}, {"y", num(level.slingshot.y)}};
    if (level.slingshot.maxForceN)
        sling["max_force_n"] = num(*level.slingshot.maxForceN);
    if (level.slingshot.maxPullM)
        sling["max_pull_m"] = num(*level.slingshot.maxPullM);
    if (level.slingshot.bandMassKg)
        sling["band_mass_kg"] = num(*level.slingshot.bandMassKg);
    root["slingshot"] = std::move(sling);
    root["birds"] = level.birds;
    if (level.customBird)
        root["custom_bird"] = {{"mass_kg", num(level.customBird->massKg)},
                               {"diameter_m", num(level.customBird->diameterM)},
                               {"drag_coefficient", num(level.customBird->dragCoefficient)}};
    if (!level.blocks.empty())
    {
        OrderedJson blocks = OrderedJson::array();
        for (const BlockDef& b : level.blocks)
            blocks.push_back(blockJson(b));
        root["blocks"] = std::move(blocks);
    }
    OrderedJson pigs = OrderedJson::array();
    for (const PigDef& p : level.pigs)
        pigs.push_back({{"type", p.type}, {"x", num(p.x)}, {"y", num(p.y)}});
    root["pigs"] = std::move(pigs);
    if (!level.terrain.empty())
    {
        OrderedJson terrain = OrderedJson::array();
        for (const TerrainDef& t : level.terrain)
        {
            if (t.isPolygon())
            {
                OrderedJson points = OrderedJson::array();
                for (const auto& [x, y] : t.points)
                    points.push_back(OrderedJson::array({num(x), num(y)}));
                terrain.push_back({{"points", std::move(points)}});
                continue;
            }
            OrderedJson item = {{"x", num(t.x)}, {"y", num(t.y)}, {"w", num(t.widthM)}, {"h", num(t.heightM)}};
            if (t.angleDeg != 0.0)
                item["angle_deg"] = num(t.angleDeg);
            terrain.push_back(std::move(item));
        }
        root["terrain"] = std::move(terrain);
    }
    if (OrderedJson environment = environmentJson(level.environment); !environment.empty())
        root["environment"] = std::move(environment);
    if (level.theme)
        root["theme"] = worldThemeName(*level.theme);
    if (!level.materials.empty())
        root["materials"] = materialsJson(level.materials);
    if (level.starScores != defaults.starScores)
        root["stars"] = level.starScores;
    if (level.timeLimitS)
        root["time_limit_s"] = num(*level.timeLimitS);
    if (level.referenceShot)
        root["reference_shot"] =
            OrderedJson::array({num(level.referenceShot->angleDeg), num(level.referenceShot->speedMps)});

    // The top level and the lists designers edit line by line are always one item per line.
    std::string out = "{\n";
    std::size_t i = 0;
    for (const auto& [key, value] : root.items())
    {
        out += "  " + text(key) + ": ";
        const bool listed = key == "hints" || key == "claims" || key == "blocks" || key == "pigs" || key == "terrain";
        print(out, value, 2, 4 + text(key).size(), listed);
        out += ++i < root.size() ? ",\n" : "\n";
    }
    return out + "}\n";
}

std::string schemaReferenceFor(const std::filesystem::path& levelPath, const std::filesystem::path& schemaPath)
{
    std::error_code ec;
    const auto folder = std::filesystem::weakly_canonical(std::filesystem::absolute(levelPath, ec).parent_path(), ec);
    const auto schema = std::filesystem::weakly_canonical(std::filesystem::absolute(schemaPath, ec), ec);
    if (ec)
        return schemaPath.generic_string();
    const auto relative = schema.lexically_relative(folder);
    return relative.empty() ? schema.generic_string() : relative.generic_string();
}

void saveLevel(const LevelDef& level, const std::filesystem::path& path, const std::filesystem::path& schemaPath)
{
    writeFileAtomically(path, writeLevelJson(level, schemaReferenceFor(path, schemaPath)));
}

} // namespace abalike
