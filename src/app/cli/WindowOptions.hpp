#pragma once

#include "cli/Arguments.hpp"
#include "shell/AppOptions.hpp"
#include "shell/Display.hpp"

#include <CLI/CLI.hpp>
#include <abalike/save/SaveStore.hpp>
#include <optional>
#include <string>

namespace abalike::app
{

/// The options every command that opens the game window takes (play, edit): offline frames, a screenshot, an input
/// script, a trace and the window size.
struct WindowArgs
{
    std::optional<int> frames;
    std::string screenshot;
    std::string script;
    std::string trace;
    std::string size;
    std::string wording;
    std::string mode;
    std::string settings;
};

/// Registers --frames, --screenshot, --script, --trace, --size, --wording, --mode and --settings on a subcommand.
void addWindowOptions(CLI::App& command, WindowArgs& args);

/// Checks --frames, --screenshot, --trace, --size and --wording and fills them into options. Throws UsageError.
void applyWindowOptions(const WindowArgs& args, AppOptions& options);

/// Reads --settings, if given, into the store in place of the saved settings (never written back). Throws UsageError
/// naming the file and what is wrong in it.
void pinWindowSettings(const WindowArgs& args, SaveStore& store);

/// Loads --script, if given: its coordinates are window pixels of the window the run opens (--size, else the saved
/// size). Its errors throw as the script loader reports them.
void loadWindowScript(const WindowArgs& args, const SaveStore& store, AppOptions& options);

} // namespace abalike::app
