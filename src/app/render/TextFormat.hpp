#pragma once

#include <string>

namespace abalike::app
{

/// A number with a fixed count of decimals ("21.0").
std::string formatFixed(double value, int decimals);
/// formatFixed with its sign always shown ("+0.12", "\u22120.12"), and none on a value that rounds to zero ("0.00").
std::string formatSigned(double value, int decimals);

/// Points with thousands separators ("25,000").
std::string formatPoints(int points);

/// A small distance in the unit that reads best: "0.004 mm", "0.3 mm", "2.5 cm", "1.20 m".
std::string formatDistance(double metres);

} // namespace abalike::app
