#include "cli/WindowOptions.hpp"

#include "cli/Arguments.hpp"
#include "cli/UsageError.hpp"
#include "input/ScriptedInput.hpp"

#include <abalike/save/SaveError.hpp>

#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace abalike::app
{

namespace
{
void requireFolderOf(const std::string& file, const char* option)
{
    const auto folder = std::filesystem::path(file).parent_path();
    std::error_code ec;
    if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
        throw UsageError(std::string(option) + ": folder " + folder.string() + " does not exist");
}
} // namespace

void addWindowOptions(CLI::App& command, WindowArgs& args)
{
    command.add_option("--frames", args.frames, "exit after N frames (game time advances 1/60 s per frame)");
    command.add_option("--screenshot", args.screenshot, "save the last frame to this PNG file");
    command.add_option("--script", args.script,
                       "JSON array of timed input events (keys, mouse, wheel, text) injected like real input");
    command.add_option("--trace", args.trace, "write what happens (screens, levels, shots, results) as JSON lines");
    command.add_option("--size", args.size, "window size WIDTHxHEIGHT (default: the saved size, 1280x720 at first)");
    addWordingOption(command, args.wording);
    command.add_option("--mode", args.mode,
                       "game (the genre's play: a short preview, a power bar, no physics sentences) or learn (the full "
                       "preview, numbers with units, a sentence of physics after every shot); default: the saved "
                       "setting, game at first");
    command.add_option(
        "--settings", args.settings,
        "read the settings from this file (settings.json's format) instead of the saved ones; changes in "
        "this run are never written, so a class's prepared scripts behave the same on every machine");
}

void applyWindowOptions(const WindowArgs& args, AppOptions& options)
{
    if (args.frames)
    {
        if (*args.frames <= 0)
            throw UsageError("--frames: must be > 0, got " + std::to_string(*args.frames));
        options.frames = args.frames;
    }
    if (!args.screenshot.empty())
    {
        requireFolderOf(args.screenshot, "--screenshot");
        options.screenshotPath = args.screenshot;
    }
    if (!args.trace.empty())
    {
        requireFolderOf(args.trace, "--trace");
        options.tracePath = args.trace;
    }
    if (!args.size.empty())
    {
        const auto [width, height] = parseSize(args.size);
        options.width = width;
        options.height = height;
    }
    options.wording = parseWordingOption(args.wording);
    if (!args.mode.empty())
    {
        options.mode = parsePlayMode(args.mode);
        if (!options.mode)
            throw UsageError("--mode: expected game or learn, got \"" + args.mode + "\"");
    }
}

void pinWindowSettings(const WindowArgs& args, SaveStore& store)
{
    if (args.settings.empty())
        return;
    try
    {
        store.pinSettings(readSettingsFile(args.settings));
    }
    catch (const std::exception& e)
    {
        throw UsageError(std::string("--settings: ") + e.what());
    }
}

void loadWindowScript(const WindowArgs& args, const SaveStore& store, AppOptions& options)
{
    if (!args.script.empty())
    {
        const unsigned width = options.width.value_or(store.settings().windowWidth);
        const unsigned height = options.height.value_or(store.settings().windowHeight);
        options.script = loadScript(args.script, width, height);
        options.hasScript = true;
    }
}

} // namespace abalike::app
