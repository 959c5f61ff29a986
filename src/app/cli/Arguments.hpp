#pragma once

#include <abalike/game/GameSession.hpp>

#include <string>
#include <utility>
#include <vector>

namespace abalike::app
{

/// Parses a number written on the command line; throws UsageError naming the option if it is not a finite number.
double parseFinite(const std::string& text, const std::string& option);

/// Throws UsageError unless value is finite; used for values CLI11 already converted.
void requireFinite(double value, const std::string& option);

/// "ANGLE,SPEED" or "ANGLE,SPEED,ABILITY_AT_S" -> shot; throws UsageError.
ScriptedShot parseShot(const std::string& text);

/// "A,B" -> two finite numbers; throws UsageError.
std::pair<double, double> parsePair(const std::string& text, const std::string& option);

/// "WxH" -> window size in pixels; throws UsageError.
std::pair<unsigned, unsigned> parseSize(const std::string& text);

} // namespace abalike::app
