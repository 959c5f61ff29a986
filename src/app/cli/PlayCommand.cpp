#include "cli/Arguments.hpp"
#include "cli/Commands.hpp"
#include "cli/DataPaths.hpp"
#include "cli/UsageError.hpp"
#include "screens/PlayOptions.hpp"

#include <abalike/level/LevelIO.hpp>

#include <filesystem>
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
    std::string size = "1280x720";
};

int runPlayCommand(const PlayArgs& a)
{
    PlayOptions options;
    if (a.level.empty())
        options.levelPaths = loadCampaign(campaignManifest());
    else
        options.levelPaths.push_back(a.level);
    if (a.frames)
    {
        if (*a.frames <= 0)
            throw UsageError("--frames: must be > 0, got " + std::to_string(*a.frames));
        options.frames = a.frames;
    }
    if (!a.screenshot.empty())
    {
        const auto folder = std::filesystem::path(a.screenshot).parent_path();
        std::error_code ec;
        if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
            throw UsageError("--screenshot: folder " + folder.string() + " does not exist");
        options.screenshotPath = a.screenshot;
    }
    for (const std::string& text : a.shots)
        options.shots.push_back(parseShot(text));
    std::tie(options.width, options.height) = parseSize(a.size);
    // Check every level before opening a window, so a bad file is one clear line, not a flash of a window.
    for (const std::string& path : options.levelPaths)
        loadLevel(path, Catalog::builtin());
    return runPlay(options);
}

} // namespace

CommandRunner addPlayCommand(CLI::App& app)
{
    auto args = std::make_shared<PlayArgs>();
    CLI::App* cmd = app.add_subcommand("play", "Open the game window (the bundled campaign when no level is given)");
    cmd->add_option("level", args->level, "level JSON file");
    cmd->add_option("--frames", args->frames, "exit after N frames (game time advances 1/60 s per frame)");
    cmd->add_option("--screenshot", args->screenshot, "save the last frame to this PNG file");
    cmd->add_option("--shot", args->shots, "ANGLE,SPEED to fire when a bird is ready; repeat for more")
        ->allow_extra_args(false);
    cmd->add_option("--size", args->size, "window size WIDTHxHEIGHT (default 1280x720)");
    return [args] { return runPlayCommand(*args); };
}

} // namespace abalike::app
