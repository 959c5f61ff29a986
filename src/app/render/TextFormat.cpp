#include "render/TextFormat.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace abalike::app
{

std::string formatFixed(double value, int decimals)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    std::string text = buffer;
    // A small negative value rounds to "-0.00": a class reads that as a number below zero.
    if (text.starts_with('-') && text.find_first_not_of("-0.") == std::string::npos)
        text.erase(0, 1);
    return text;
}

std::string formatSigned(double value, int decimals)
{
    const std::string text = formatFixed(value, decimals);
    if (text.find_first_not_of("0.") == std::string::npos)
        return text;
    return text.starts_with('-') ? "\u2212" + text.substr(1) : "+" + text;
}

std::string formatPoints(int points)
{
    const std::string digits = std::to_string(std::abs(static_cast<long long>(points)));
    std::string grouped = points < 0 ? "-" : "";
    for (std::size_t i = 0; i < digits.size(); ++i)
    {
        if (i > 0 && (digits.size() - i) % 3 == 0)
            grouped += ',';
        grouped += digits[i];
    }
    return grouped;
}

std::string formatDistance(double metres)
{
    const double d = std::abs(metres);
    if (d < 1e-6)
        return "< 0.001 mm";
    if (d < 1e-4)
        return formatFixed(d * 1e3, 3) + " mm";
    if (d < 1e-2)
        return formatFixed(d * 1e3, 1) + " mm";
    if (d < 1.0)
        return formatFixed(d * 1e2, 1) + " cm";
    return formatFixed(d, 2) + " m";
}

} // namespace abalike::app
