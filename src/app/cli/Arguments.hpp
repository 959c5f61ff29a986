#pragma once

#include <abalike/game/GameSession.hpp>
#include <abalike/save/Settings.hpp>

#include <CLI/CLI.hpp>
#include <array>
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

/// "A,B,C" -> three finite numbers; throws UsageError naming the option and the expected form.
std::array<double, 3> parseTriple(const std::string& text, const std::string& option);

/// The flight-model options as written on the command line (predict, walkthrough, chart range share them).
struct FlightModelArgs
{
    std::string gravity = "9.81", mass = "1", linearDrag = "0", quadraticDrag = "0", wind;
    std::string gustSine;
    std::vector<std::string> gustSteps;
};

/// Registers --gravity --mass --linear-drag --quadratic-drag --wind --gust-sine --gust-step on a command; with
/// gusts false, only the first five.
void addFlightModelOptions(CLI::App& command, FlightModelArgs& args, bool gusts = true);

/// The flight model the options describe; throws UsageError naming the option for anything invalid.
FlightModel parseFlightModel(const FlightModelArgs& args);

/// Registers --wording (school or university) on a subcommand (play, edit, simulate).
void addWordingOption(CLI::App& command, std::string& wording);
/// The wording --wording asks for; nullopt when it was not given. Throws UsageError for any other word.
std::optional<Wording> parseWordingOption(const std::string& text);

} // namespace abalike::app
