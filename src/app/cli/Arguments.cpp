#include "cli/Arguments.hpp"

#include <CLI/CLI.hpp>

#include "cli/UsageError.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

namespace abalike::app
{

double parseFinite(const std::string& text, const std::string& option)
{
    double value = 0.0;
    const char* begin = text.data();
    const char* end = begin + text.size();
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec == std::errc::result_out_of_range)
        throw UsageError(option + ": " + text + " is out of the range of a double");
    if (ec != std::errc() || ptr != end || text.empty())
        throw UsageError(option + ": expected a number, got \"" + text + "\"");
    requireFinite(value, option);
    return value;
}

void requireFinite(double value, const std::string& option)
{
    if (!std::isfinite(value))
        throw UsageError(option + ": expected a finite number, got " + std::to_string(value));
}

std::pair<double, double> parsePair(const std::string& text, const std::string& option)
{
    const auto comma = text.find(',');
    if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
        throw UsageError(option + ": expected two numbers as A,B, got \"" + text + "\"");
    return {parseFinite(text.substr(0, comma), option), parseFinite(text.substr(comma + 1), option)};
}

ScriptedShot parseShot(const std::string& text)
{
    // ANGLE,SPEED or ANGLE,SPEED,ABILITY_AT_S (seconds after launch to use the bird's ability).
    const auto second = text.find(',', text.find(',') + 1);
    const std::string pair = second == std::string::npos ? text : text.substr(0, second);
    const auto [angle, speed] = parsePair(pair, "--shot ANGLE,SPEED[,ABILITY_AT_S]");
    if (angle < -90.0 || angle > 90.0)
        throw UsageError("--shot: angle must be between -90 and 90 degrees, got " + text.substr(0, text.find(',')));
    if (speed < 0.0)
        throw UsageError("--shot: speed must be >= 0 m/s, got " + pair.substr(pair.find(',') + 1));
    ScriptedShot shot{angle, speed};
    if (second != std::string::npos)
    {
        const double at = parseFinite(text.substr(second + 1), "--shot ANGLE,SPEED,ABILITY_AT_S");
        if (at < 0.0)
            throw UsageError("--shot: the ability time must be >= 0 s after launch, got " + text.substr(second + 1));
        shot.abilityAtS = at;
    }
    return shot;
}

std::pair<unsigned, unsigned> parseSize(const std::string& text)
{
    const auto x = text.find('x');
    unsigned w = 0;
    unsigned h = 0;
    if (x != std::string::npos)
    {
        const auto r1 = std::from_chars(text.data(), text.data() + x, w);
        const auto r2 = std::from_chars(text.data() + x + 1, text.data() + text.size(), h);
        if (r1.ec == std::errc() && r1.ptr == text.data() + x && r2.ec == std::errc() &&
            r2.ptr == text.data() + text.size() && w >= 320 && h >= 240 && w <= 7680 && h <= 4320)
            return {w, h};
    }
    throw UsageError("--size: expected WIDTHxHEIGHT between 320x240 and 7680x4320, got \"" + text + "\"");
}

std::array<double, 3> parseTriple(const std::string& text, const std::string& option)
{
    std::array<double, 3> values{};
    std::stringstream parts(text);
    std::string part;
    std::size_t count = 0;
    while (std::getline(parts, part, ','))
    {
        if (count == values.size())
            throw UsageError(option + ": expected three numbers, got \"" + text + "\"");
        values[count++] = parseFinite(part, option);
    }
    if (count != values.size())
        throw UsageError(option + ": expected three numbers, got \"" + text + "\"");
    return values;
}

namespace
{

/// Gusts from --gust-sine AX,AY,PERIOD or repeated --gust-step T,WX,WY; nullopt when neither is given.
std::optional<GustDef> parseGusts(const FlightModelArgs& a)
{
    if (!a.gustSine.empty() && !a.gustSteps.empty())
        throw UsageError("--gust-sine and --gust-step cannot be combined: a flight has one kind of gust");
    if (!a.gustSine.empty())
    {
        const auto [ax, ay, period] = parseTriple(a.gustSine, "--gust-sine AX,AY,PERIOD");
        if (period <= 0.0)
            throw UsageError("--gust-sine: the period must be > 0 s, got " + std::to_string(period));
        GustDef gusts;
        gusts.kind = GustDef::Kind::Sine;
        gusts.amplitudeX = ax;
        gusts.amplitudeY = ay;
        gusts.periodS = period;
        return gusts;
    }
    if (a.gustSteps.empty())
        return std::nullopt;
    GustDef gusts;
    gusts.kind = GustDef::Kind::Steps;
    for (const std::string& text : a.gustSteps)
    {
        const auto [start, wx, wy] = parseTriple(text, "--gust-step T,WX,WY");
        gusts.steps.push_back({start, wx, wy});
    }
    std::sort(gusts.steps.begin(), gusts.steps.end(),
              [](const GustDef::Step& x, const GustDef::Step& y) { return x.startS < y.startS; });
    return gusts;
}

} // namespace

void addFlightModelOptions(CLI::App& cmd, FlightModelArgs& args, bool gusts)
{
    cmd.add_option("--gravity", args.gravity, "magnitude of g along -y in m/s^2 (default 9.81)");
    cmd.add_option("--mass", args.mass, "bird mass in kg (default 1)");
    cmd.add_option("--linear-drag", args.linearDrag, "b in F = -b (v - w), kg/s (default 0)");
    cmd.add_option("--quadratic-drag", args.quadraticDrag, "c in F = -c |v - w| (v - w), kg/m (default 0)");
    cmd.add_option("--wind", args.wind, "constant wind WX,WY in m/s (acts through drag)");
    if (!gusts)
        return;
    cmd.add_option("--gust-sine", args.gustSine, "gusts w(t) = A sin(2 pi t / PERIOD) added to the wind: AX,AY,PERIOD");
    cmd.add_option("--gust-step", args.gustSteps, "a gust step T,WX,WY: wind added from T s on (repeatable)");
}

FlightModel parseFlightModel(const FlightModelArgs& a)
{
    FlightModel model;
    model.gravity = parseFinite(a.gravity, "--gravity");
    model.massKg = parseFinite(a.mass, "--mass");
    model.linearDrag = parseFinite(a.linearDrag, "--linear-drag");
    model.quadraticDrag = parseFinite(a.quadraticDrag, "--quadratic-drag");
    if (!a.wind.empty())
        std::tie(model.windX, model.windY) = parsePair(a.wind, "--wind WX,WY");
    model.gusts = parseGusts(a);
    if (const std::string problem = validateFlightModel(model); !problem.empty())
        throw UsageError(problem);
    return model;
}

void addWordingOption(CLI::App& command, std::string& wording)
{
    command.add_option("--wording", wording,
                       "school (ages 14-16: no RK4, Box2D or other machinery in any text) or university (full depth); "
                       "default: the saved setting, school at first");
}

std::optional<Wording> parseWordingOption(const std::string& text)
{
    if (text.empty())
        return std::nullopt;
    if (const std::optional<Wording> wording = parseWording(text))
        return wording;
    throw UsageError("--wording: expected school or university, got \"" + text + "\"");
}

} // namespace abalike::app
