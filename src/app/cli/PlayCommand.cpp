#include "cli/Arguments.hpp"
#include "cli/Commands.hpp"
#include "cli/DataPaths.hpp"
#include "cli/UsageError.hpp"
#include "input/ScriptedInput.hpp"
#include "render/Font.hpp"
#include "screens/App.hpp"

#include <abalike/level/LevelIO.hpp>
#include <abalike/save/DataDirectory.hpp>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>

namespace abalike::app
{

namespace
{

struct PlayArgs
{
    std::string level;
    std::optional<int> frames;
    std::string screenshot;
    std::vector<std::string> shots;
    std::string size;
    std::string script;
    std::string trace;
};

void requireFolderOf(const std::string& file, const char* option)
{
    const auto folder = std::filesystem::path(file).parent_path();
    std::error_code ec;
    if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
        throw UsageError(std::string(option) + ": folder " + folder.string() + " does not exist");
}

int runPlayCommand(const PlayArgs& a)
{
    AppOptions options;
    options.levelPath = a.level;
    options.campaignPath = campaignManifest();
    if (a.frames)
    {
        if (*a.frames <= 0)
            throw UsageError("--frames: must be > 0, got " + std::to_string(*a.frames));
        options.frames = a.frames;
    }
    if (!a.screenshot.empty())
    {
        requireFolderOf(a.screenshot, "--screenshot");
        options.screenshotPath = a.screenshot;
    }
    if (!a.trace.empty())
    {
        requireFolderOf(a.trace, "--trace");
        options.tracePath = a.trace;
    }
    for (const std::string& text : a.shots)
        options.shots.push_back(parseShot(text));
    if (!a.size.empty())
    {
        const auto [width, height] = parseSize(a.size);
        options.width = width;
        options.height = height;
    }

    // Everything a run needs is checked before a window opens, so a bad file is one clear line, not a flash of a
    // window: the level, the campaign and the script.
    Campaign campaign;
    if (!a.level.empty())
    {
        options.level = loadLevel(a.level, Catalog::builtin());
        try
        {
            campaign = loadCampaignLevels(options.campaignPath, Catalog::builtin());
        }
        catch (const LevelLoadError& error)
        {
            // A designer playing their own level is not stopped by a broken campaign; they only lose "next level".
            std::cerr << "abalike: the campaign " << options.campaignPath
                      << " does not load, so level select is unavailable ("
                      << (error.issues().empty() ? error.what() : error.issues().front().format()) << ")\n";
        }
    }
    else
        campaign = loadCampaignLevels(options.campaignPath, Catalog::builtin());

    SaveStore store(defaultDataDirectory());
    store.load();
    if (!a.script.empty())
    {
        // Coordinates are window pixels of the window the run opens: --size, else the saved size.
        const unsigned width = options.width.value_or(store.settings().windowWidth);
        const unsigned height = options.height.value_or(store.settings().windowHeight);
        options.script = loadScript(a.script, width, height);
        options.hasScript = true;
    }

#if defined(__unix__) && !defined(__APPLE__)
    // SFML aborts the process when it cannot reach an X server; say why instead.
    if (std::getenv("DISPLAY") == nullptr)
    {
        std::cerr << "abalike: no display (DISPLAY is not set); for offline frames run under xvfb-run\n";
        return kUsageExitCode;
    }
#endif
    App app(std::move(options), std::move(campaign), std::move(store), loadGameFont());
    return app.run();
}

} // namespace

CommandRunner addPlayCommand(CLI::App& app)
{
    auto args = std::make_shared<PlayArgs>();
    CLI::App* cmd = app.add_subcommand(
        "play", "Open the game window: the title screen, or straight into a level when one is given");
    cmd->add_option("level", args->level, "level JSON file to play directly (live reload while it runs)");
    cmd->add_option("--frames", args->frames, "exit after N frames (game time advances 1/60 s per frame)");
    cmd->add_option("--screenshot", args->screenshot, "save the last frame to this PNG file");
    cmd->add_option("--shot", args->shots,
                    "ANGLE,SPEED[,ABILITY_AT_S] to fire when a bird is ready; repeat for more (with no level: the "
                    "campaign's first level)")
        ->allow_extra_args(false);
    cmd->add_option("--script", args->script,
                    "JSON array of timed input events (keys, mouse, wheel, text) injected like real input");
    cmd->add_option("--trace", args->trace, "write what happens (screens, levels, shots, results) as JSON lines");
    cmd->add_option("--size", args->size, "window size WIDTHxHEIGHT (default: the saved size, 1280x720 at first)");
    return [args]
    {
        return runPlayCommand(*args);
    };
}

} // namespace abalike::app
