#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <ostream>
#include <string>

namespace abalike::app
{

/// Each subcommand registers its options on the parser and returns what runs it after parsing; the runner
/// returns the exit code and throws UsageError for bad input.
using CommandRunner = std::function<int()>;

CommandRunner addPredictCommand(CLI::App& app);
CommandRunner addSimulateCommand(CLI::App& app);
CommandRunner addPlayCommand(CLI::App& app);
CommandRunner addEditCommand(CLI::App& app);
CommandRunner addBenchCommand(CLI::App& app);
CommandRunner addCheckCommand(CLI::App& app);
CommandRunner addSolveCommand(CLI::App& app);
CommandRunner addWalkthroughCommand(CLI::App& app);
CommandRunner addChartCommand(CLI::App& app);
CommandRunner addFmtCommand(CLI::App& app);
CommandRunner addImportCommand(CLI::App& app);
CommandRunner addGenerateCommand(CLI::App& app);

/// `abalike check MANIFEST` for `play --pack`: true when every level passes; else the failing files' lines, as
/// check prints them, go to out.
bool packPassesCheck(const std::string& manifest, std::ostream& out);

} // namespace abalike::app
