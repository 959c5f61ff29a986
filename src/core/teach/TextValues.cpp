#include <abalike/level/LevelCatalog.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <abalike/teach/RangeChart.hpp>
#include <abalike/teach/TextValues.hpp>

#include "level/LevelReader.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace abalike
{

const std::vector<TextValueName>& textValueNames()
{
    static const std::vector<TextValueName> names = []
    {
        // The level's and the birds' values, then the abilities' numbers their catalog blocks declare, then the air's
        // and the rest.
        std::vector<TextValueName> list{
            {"v_max", "BIRD", "launch speed at full pull, v0 = sqrt(2E/(m + m_b)) (at most the catalog's speed cap)",
             "m/s", 1},
            {"p_max", "BIRD", "momentum at full pull, m v0", "N s", 0},
            {"p_rebound", "BIRD",
             "the most one head-on hit at full pull pushes, (1 + e) m v0: the bird stops and rebounds with the "
             "game's bounciness e (the bird's restitution; Box2D takes the larger of the two bodies')",
             "N s", 0},
            {"e_bird", "BIRD", "the bird's kinetic energy at full pull, 1/2 m v0^2: its share m/(m + m_b) of E", "J",
             0},
            {"share", "BIRD", "the share of the band's energy the bird takes, m/(m + m_b)", "%", 0},
            {"mass", "BIRD", "the bird's mass", "kg", -1},
            {"radius", "BIRD", "the bird's radius", "m", -1},
            {"energy", "", "energy the band stores at full pull, E = 1/2 F x", "J", 0},
            {"force", "", "the band's force at full pull (max_force_n)", "N", 0},
            {"pull", "", "the full pull (max_pull_m)", "m", -1},
            {"band_mass", "", "the band's moving mass m_b (band_mass_kg)", "kg", -1},
            {"range_flat", "BIRD", "v_max^2 / g: the range at 45 degrees in vacuum from ground level", "m", 1},
            {"best_angle", "BIRD",
             "the angle that throws farthest at full pull, in this level's air, from its slingshot", "degrees", 1},
            {"best_range", "BIRD", "that farthest range, to the ground", "m", 1},
            {"vacuum_best_angle", "BIRD", "best_angle with no air (from the slingshot's height)", "degrees", 1},
            {"vacuum_best_range", "BIRD", "best_range with no air (from the slingshot's height)", "m", 1},
            {"calm_best_angle", "BIRD", "best_angle in this level's air with no wind (still air)", "degrees", 1},
            {"calm_best_range", "BIRD", "best_range in this level's air with no wind (still air)", "m", 1},
            {"terminal", "BIRD", "terminal speed in this air, sqrt(m g / c) with c = 1/2 rho Cd A", "m/s", 1},
        };
        for (const AbilityTextValue& value : Catalog::builtin().abilityTextValues())
            list.push_back({value.name.c_str(), "", value.meaning.c_str(), value.unit.c_str(), -1});
        const std::vector<TextValueName> rest{
            {"g", "", "gravity", "m/s^2", -1},
            {"rho", "", "air density (0: vacuum)", "kg/m^3", -1},
            {"wind", "", "speed of the constant wind", "m/s", -1},
            {"gust_t", "N", "time gust step N starts, after launch (steps count from 1)", "s", -1},
            {"gust_wx", "N", "horizontal wind of gust step N (positive: towards the pigs)", "m/s", -1},
            {"gust_period", "", "period of a sine gust", "s", -1},
            {"gust_amplitude", "", "largest wind of a sine gust", "m/s", -1},
            {"launch_height", "", "height of the slingshot's pouch above the ground", "m", -1},
            {"time_limit", "", "the level's time limit", "s", -1},
            {"strength", "MATERIAL", "impulse a block absorbs before it breaks", "N s", -1},
            {"density", "MATERIAL", "bulk density of the material", "kg/m^3", -1},
            {"areal_density", "MATERIAL", "mass per square metre of a 2D block (bulk density x slab depth)", "kg/m^2",
             -1},
            {"friction", "MATERIAL", "friction coefficient", "", -1},
            {"health", "PIG", "impulse a pig absorbs before it is defeated", "N s", -1},
            {"earth_g", "", "Earth's gravity, 9.81", "m/s^2", -1},
            {"earth_rho", "", "Earth's air density at sea level, 1.2", "kg/m^3", -1},
        };
        list.insert(list.end(), rest.begin(), rest.end());
        for (std::size_t i = 0; i < list.size(); ++i)
            for (std::size_t j = 0; j < i; ++j)
                if (std::string_view(list[i].name) == list[j].name)
                    throw std::logic_error("the placeholder \"" + std::string(list[i].name) +
                                           "\" is named twice (an ability's text_values in the catalog?)");
        return list;
    }();
    return names;
}

namespace
{

const TextValueName* findName(std::string_view name)
{
    for (const TextValueName& n : textValueNames())
        if (name == n.name)
            return &n;
    return nullptr;
}

std::string knownNames()
{
    std::string list;
    for (const TextValueName& n : textValueNames())
    {
        if (!list.empty())
            list += ", ";
        list += n.name;
        if (*n.argument != '\0')
            list += std::string(":") + n.argument;
    }
    return list;
}

/// "(did you mean "v_max"?)" for a near miss, else "(known: ...)" with every name.
std::string suggestedName(std::string_view name)
{
    std::vector<std::string> names;
    for (const TextValueName& n : textValueNames())
        names.emplace_back(n.name);
    if (const std::optional<std::string> suggestion = closestMatch(std::string(name), names))
        return "(did you mean \"" + *suggestion + "\"?)";
    return "(known: " + knownNames() + ")";
}

/// "{name:argument}" or "{name}", for messages.
std::string braced(std::string_view name, std::string_view argument = {})
{
    std::string text(1, '{');
    text.append(name);
    if (!argument.empty())
        text.append(1, ':').append(argument);
    return text.append(1, '}');
}

[[noreturn]] void fail(const std::string& message)
{
    throw TextValueError(message, 0);
}

const BirdType& birdArgument(const Catalog& catalog, std::string_view name, std::string_view argument)
{
    if (const BirdType* bird = catalog.findBird(argument))
        return *bird;
    fail(braced(name, argument) + ": no bird named \"" + std::string(argument) +
         "\" (red, blue, yellow, black, white, or the level's custom bird)");
}

const Material& materialArgument(const Catalog& catalog, std::string_view name, std::string_view argument)
{
    if (const Material* material = catalog.findMaterial(argument))
        return *material;
    fail(braced(name, argument) + ": no material named \"" + std::string(argument) + "\"");
}

const GustDef::Step& gustStep(const LevelDef& level, std::string_view name, std::string_view argument)
{
    const auto& gusts = level.environment.gusts;
    const std::string label = braced(name, argument);
    if (!gusts || gusts->kind != GustDef::Kind::Steps)
        fail(label + ": the level has no gust steps");
    std::size_t index = 0;
    for (char c : argument)
    {
        if (!std::isdigit(static_cast<unsigned char>(c)) || index > 1000)
            fail(label + ": expected a step number from 1");
        index = index * 10 + static_cast<std::size_t>(c - '0');
    }
    if (argument.empty() || index < 1 || index > gusts->steps.size())
        fail(label + ": the level has " + std::to_string(gusts->steps.size()) + " gust steps (from 1)");
    return gusts->steps[index - 1];
}

const GustDef& sineGust(const LevelDef& level, std::string_view name)
{
    const auto& gusts = level.environment.gusts;
    if (!gusts || gusts->kind != GustDef::Kind::Sine)
        fail(braced(name) + ": the level has no sine gust");
    return *gusts;
}

/// What of the level's air a chart flies in.
enum class Air
{
    AsItIs, ///< drag, wind and gusts
    Calm,   ///< drag without wind or gusts: still air
    None,   ///< vacuum
};

/// The best range over launch angles from 0 to 89 degrees at full pull.
RangeChart fullPullChart(const LevelDef& level, const Catalog& catalog, const BirdType& bird, Air air)
{
    RangeLaunch launch;
    launch.model = levelFlightModel(level.environment, bird);
    if (air != Air::AsItIs)
    {
        launch.model.windX = launch.model.windY = 0.0;
        launch.model.gusts.reset();
    }
    if (air == Air::None)
        launch.model.linearDrag = launch.model.quadraticDrag = 0.0;
    launch.speedMps = maxLaunchSpeed(level, bird, catalog);
    launch.heightM = std::max(0.0, level.slingshot.y - level.groundY);
    return rangeChart(launch, 0.0, 89.0, 1.0);
}

double chartValue(const RangeChart& chart, bool angle, std::string_view name)
{
    const std::optional<double> value = angle ? chart.bestAngleDeg : chart.bestRangeM;
    if (!value)
        fail(braced(name) + ": no launch angle lands in this level");
    return *value;
}

/// A value, and whether the name takes an argument at all (checked before any computing). `seen` is the catalog as
/// the level sees it (levelCatalog), made once per text by the caller.
double evaluate(const LevelDef& level, const Catalog& seen, std::string_view name, std::string_view argument,
                bool compute)
{
    const TextValueName* known = findName(name);
    if (known == nullptr)
        fail("unknown value \"" + std::string(name) + "\" " + suggestedName(name));
    const bool wantsArgument = *known->argument != '\0';
    if (wantsArgument && argument.empty())
        fail(braced(name) + " needs " + known->argument + ", as " + braced(name, known->argument));
    if (!wantsArgument && !argument.empty())
        fail(braced(name) + " takes no argument, got \":" + std::string(argument) + "\"");

    const EnvironmentDef& air = level.environment;
    const std::string_view arg = argument;
    if (std::string_view(known->argument) == "BIRD")
    {
        const BirdType& bird = birdArgument(seen, name, arg);
        if (!compute)
            return 0.0;
        const double speed = maxLaunchSpeed(level, bird, seen);
        if (name == "v_max")
            return speed;
        if (name == "p_max")
            return bird.massKg * speed;
        if (name == "p_rebound")
            return (1.0 + bird.restitution) * bird.massKg * speed;
        if (name == "e_bird")
            return 0.5 * bird.massKg * speed * speed;
        if (name == "share")
            return 100.0 * slingshotBand(level, bird, seen).birdShare();
        if (name == "mass")
            return bird.massKg;
        if (name == "radius")
            return bird.radiusM;
        if (name == "range_flat")
        {
            if (air.gravity <= 0.0)
                fail(braced("range_flat", arg) + ": the level has no gravity");
            return speed * speed / air.gravity;
        }
        if (name == "terminal")
        {
            const double c = quadraticDragCoefficient(air.airDensity, bird.dragCoefficient, bird.radiusM);
            if (c <= 0.0)
                fail(braced("terminal", arg) + ": the level has no air");
            return std::sqrt(bird.massKg * air.gravity / c);
        }
        const Air chartAir = name.rfind("vacuum_", 0) == 0 ? Air::None
                             : name.rfind("calm_", 0) == 0 ? Air::Calm
                                                           : Air::AsItIs;
        const RangeChart chart = fullPullChart(level, seen, bird, chartAir);
        return chartValue(chart, name.find("angle") != std::string_view::npos, name);
    }
    if (std::string_view(known->argument) == "MATERIAL")
    {
        const Material& material = materialArgument(seen, name, arg);
        if (name == "strength")
            return material.strengthNs;
        if (name == "density")
            return material.bulkDensityKgPerM3;
        if (name == "areal_density")
            return material.densityKgPerM2;
        return material.friction;
    }
    if (std::string_view(known->argument) == "PIG")
    {
        if (const PigType* pig = seen.findPig(arg))
            return pig->healthNs;
        fail(braced("health", arg) + ": no pig named \"" + std::string(arg) + "\"");
    }
    if (name == "gust_t")
        return gustStep(level, name, arg).startS;
    if (name == "gust_wx")
        return gustStep(level, name, arg).windX;
    if (name == "gust_period")
        return sineGust(level, name).periodS;
    if (name == "gust_amplitude")
    {
        const GustDef& gust = sineGust(level, name);
        return std::hypot(gust.amplitudeX, gust.amplitudeY);
    }
    if (name == "time_limit")
    {
        if (!level.timeLimitS)
            fail("{time_limit}: the level has no time_limit_s");
        return *level.timeLimitS;
    }
    const BandDef band = levelBand(level, seen);
    if (name == "energy")
        return 0.5 * band.maxForceN * band.maxPullM;
    if (name == "force")
        return band.maxForceN;
    if (name == "pull")
        return band.maxPullM;
    if (name == "band_mass")
        return band.bandMassKg;
    for (const AbilityTextValue& value : Catalog::builtin().abilityTextValues())
        if (name == value.name)
        {
            const Ability* ability = seen.findAbility(value.ability);
            if (ability == nullptr)
                fail(braced(name) + ": no bird of the catalog has the " + value.ability + " ability");
            return ability->number(value.number);
        }
    if (name == "g")
        return air.gravity;
    if (name == "rho")
        return air.airDensity;
    if (name == "wind")
        return std::hypot(air.windX, air.windY);
    if (name == "launch_height")
        return std::max(0.0, level.slingshot.y - level.groundY);
    if (name == "earth_g")
        return kEarthGravity;
    return kEarthAirDensity; // earth_rho, the last name
}

/// The expression inside one pair of braces: sums, differences, products and quotients of values, numbers and
/// sqrt(...), with parentheses and a leading minus.
class Expression
{
public:
    Expression(std::string_view text, std::size_t offset, const LevelDef& level, const Catalog& catalog, bool compute)
        : m_text(text), m_offset(offset), m_level(level), m_catalog(catalog), m_compute(compute)
    {
    }

    /// The value and the decimals a lone value asks for (-1: as few as needed; 2 for an expression).
    double parse(int& decimals)
    {
        decimals = 2;
        skipSpaces();
        const TextValueName* lone = nullptr;
        const double value = sum(lone);
        skipSpaces();
        if (m_pos != m_text.size())
            error("expected + - * / or the end of the placeholder, got \"" + std::string(m_text.substr(m_pos)) + "\"",
                  m_pos);
        if (lone != nullptr && m_singleTerm)
            decimals = lone->decimals;
        return value;
    }

private:
    [[noreturn]] void error(const std::string& message, std::size_t at) const
    {
        throw TextValueError(message, m_offset + at);
    }

    void skipSpaces()
    {
        while (m_pos < m_text.size() && m_text[m_pos] == ' ')
            ++m_pos;
    }

    double sum(const TextValueName*& lone)
    {
        double value = product(lone);
        skipSpaces();
        while (m_pos < m_text.size() && (m_text[m_pos] == '+' || m_text[m_pos] == '-'))
        {
            m_singleTerm = false;
            const char op = m_text[m_pos++];
            const double right = product(lone);
            value = op == '+' ? value + right : value - right;
            skipSpaces();
        }
        return value;
    }

    double product(const TextValueName*& lone)
    {
        double value = factor(lone);
        skipSpaces();
        while (m_pos < m_text.size() && (m_text[m_pos] == '*' || m_text[m_pos] == '/'))
        {
            m_singleTerm = false;
            const char op = m_text[m_pos++];
            const std::size_t at = m_pos;
            const double right = factor(lone);
            if (op == '*')
                value *= right;
            else if (m_compute && right == 0.0)
                error("division by zero", at);
            else if (m_compute)
                value /= right;
            skipSpaces();
        }
        return value;
    }

    static bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

    double factor(const TextValueName*& lone)
    {
        skipSpaces();
        if (m_pos >= m_text.size())
            error("expected a value, a number or (", m_pos);
        const char c = m_text[m_pos];
        if (c == '-')
        {
            ++m_pos; // a negated value keeps the value's own decimals
            return -factor(lone);
        }
        if (c == '(')
        {
            ++m_pos;
            m_singleTerm = false;
            const double value = sum(lone);
            skipSpaces();
            if (m_pos >= m_text.size() || m_text[m_pos] != ')')
                error("expected )", m_pos);
            ++m_pos;
            return value;
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.')
        {
            m_singleTerm = false;
            std::size_t end = m_pos;
            while (end < m_text.size() && (std::isdigit(static_cast<unsigned char>(m_text[end])) || m_text[end] == '.'))
                ++end;
            const std::string number(m_text.substr(m_pos, end - m_pos));
            m_pos = end;
            return std::strtod(number.c_str(), nullptr);
        }
        const std::size_t start = m_pos;
        while (m_pos < m_text.size() && isNameChar(m_text[m_pos]))
            ++m_pos;
        const std::string_view name = m_text.substr(start, m_pos - start);
        if (name.empty())
            error("expected a value, a number or (, got \"" + std::string(1, c) + "\"", start);
        if (name == "sqrt")
        {
            m_singleTerm = false;
            skipSpaces();
            if (m_pos >= m_text.size() || m_text[m_pos] != '(')
                error("expected ( after sqrt", m_pos);
            const double inside = factor(lone);
            if (m_compute && inside < 0.0)
                error("sqrt of a negative value", start);
            return m_compute ? std::sqrt(inside) : 0.0;
        }
        std::string_view argument;
        if (m_pos < m_text.size() && m_text[m_pos] == ':')
        {
            const std::size_t argStart = ++m_pos;
            while (m_pos < m_text.size() && isNameChar(m_text[m_pos]))
                ++m_pos;
            argument = m_text.substr(argStart, m_pos - argStart);
        }
        lone = findName(name);
        try
        {
            return evaluate(m_level, m_catalog, name, argument, m_compute);
        }
        catch (const TextValueError& e)
        {
            error(e.what(), start);
        }
    }

    std::string_view m_text;
    std::size_t m_offset;
    std::size_t m_pos = 0;
    bool m_singleTerm = true;
    const LevelDef& m_level;
    const Catalog& m_catalog;
    bool m_compute;
};

std::string formatValue(double value, int decimals)
{
    char text[64];
    if (decimals >= 0)
    {
        std::snprintf(text, sizeof text, "%.*f", decimals, value);
        return text;
    }
    std::snprintf(text, sizeof text, "%.3f", value);
    std::string s = text;
    while (!s.empty() && s.back() == '0')
        s.pop_back();
    if (!s.empty() && s.back() == '.')
        s.pop_back();
    return s == "-0" ? "0" : s;
}

/// Only letters, digits and the expression's signs: "{v_max:red|1}" is a placeholder, "{ like this, }" is text.
bool looksLikePlaceholder(std::string_view inside)
{
    if (inside.empty())
        return false;
    for (char c : inside)
        if (!std::isalnum(static_cast<unsigned char>(c)) &&
            std::string_view("_:|.+-*/() ").find(c) == std::string_view::npos)
            return false;
    return true;
}

/// Walks the text: literal characters are appended, each placeholder is evaluated (or only checked).
std::string process(std::string_view text, const LevelDef& level, const Catalog& catalog, bool compute)
{
    std::optional<Catalog> seen;
    std::string out;
    std::size_t i = 0;
    while (i < text.size())
    {
        const char c = text[i];
        if ((c == '{' || c == '}') && i + 1 < text.size() && text[i + 1] == c)
        {
            out += c;
            i += 2;
            continue;
        }
        const std::size_t close = c == '{' ? text.find('}', i + 1) : std::string_view::npos;
        // Braces around anything else than a placeholder's characters stay as written: texts of format 1 from before
        // placeholders read as they did.
        if (c != '{' || close == std::string_view::npos || !looksLikePlaceholder(text.substr(i + 1, close - i - 1)))
        {
            out += c;
            ++i;
            continue;
        }
        std::string_view inside = text.substr(i + 1, close - i - 1);
        std::optional<int> decimals;
        if (const std::size_t bar = inside.find('|'); bar != std::string_view::npos)
        {
            const std::string_view digits = inside.substr(bar + 1);
            if (digits.size() != 1 || !std::isdigit(static_cast<unsigned char>(digits[0])))
                throw TextValueError("expected 0 to 9 decimals after |, got \"" + std::string(digits) + "\"",
                                     i + 2 + bar);
            decimals = digits[0] - '0';
            inside = inside.substr(0, bar);
        }
        if (!seen)
            seen = levelCatalog(level, catalog); // once per text, and only for a text with placeholders
        Expression expression(inside, i + 1, level, *seen, compute);
        int own = 2;
        const double value = expression.parse(own);
        if (compute)
            out += formatValue(value, decimals.value_or(own));
        i = close + 1;
    }
    return out;
}

} // namespace

double textValue(const LevelDef& level, const Catalog& catalog, std::string_view name, std::string_view argument)
{
    return evaluate(level, levelCatalog(level, catalog), name, argument, true);
}

std::string fillText(std::string_view text, const LevelDef& level, const Catalog& catalog)
{
    return process(text, level, catalog, true);
}

std::vector<TextValueError> checkText(std::string_view text, const LevelDef& level, const Catalog& catalog)
{
    try
    {
        process(text, level, catalog, false);
    }
    catch (const TextValueError& e)
    {
        return {e};
    }
    return {};
}

double evaluateExpression(std::string_view expression, const LevelDef& level, const Catalog& catalog)
{
    const Catalog seen = levelCatalog(level, catalog);
    Expression parsed(expression, 0, level, seen, true);
    int decimals = 2;
    return parsed.parse(decimals);
}

std::optional<TextValueError> checkExpression(std::string_view expression, const LevelDef& level,
                                              const Catalog& catalog)
{
    try
    {
        const Catalog seen = levelCatalog(level, catalog);
        Expression parsed(expression, 0, level, seen, false);
        int decimals = 2;
        parsed.parse(decimals);
    }
    catch (const TextValueError& e)
    {
        return e;
    }
    return std::nullopt;
}

std::string levelText(std::string_view text, const LevelDef& level, const Catalog& catalog)
{
    try
    {
        return fillText(text, level, catalog);
    }
    catch (const std::exception&)
    {
        return std::string(text);
    }
}

} // namespace abalike
