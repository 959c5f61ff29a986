#include "cli/Arguments.hpp"

#include "cli/UsageError.hpp"

#include <charconv>
#include <cmath>

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

} // namespace abalike::app
