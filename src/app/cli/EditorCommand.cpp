#include "cli/Commands.hpp"
#include "cli/UsageError.hpp"
#include "cli/WindowOptions.hpp"
#include "editor/EditorScreen.hpp"
#include "render/Font.hpp"
#include "screens/GameScreens.hpp"
#include "shell/App.hpp"
#include "shell/DataPaths.hpp"

#include <abalike/level/Campaign.hpp>
#include <abalike/save/DataDirectory.hpp>

#include <filesystem>
#include <iostream>
#include <memory>

namespace abalike::app
{

namespace
{

struct EditArgs
{
    std::string level;
    WindowArgs window;
};

int runEditCommand(const EditArgs& a)
{
    AppOptions options;
    options.campaignPath = campaignManifest();
    applyWindowOptions(a.window, options);

    // The level is read before a window opens: a file that cannot be read, or whose JSON or format is invalid,
    // exits 2 with every problem as `check` prints them (main() prints LevelLoadError). Geometry problems open.
    EditorSource source = sandboxSource();
    if (!a.level.empty())
    {
        const std::filesystem::path path(a.level);
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec))
            throw UsageError(a.level + " is a folder (expected a level file to edit)");
        if (!std::filesystem::exists(path, ec) && path.has_parent_path() &&
            !std::filesystem::is_directory(path.parent_path(), ec))
            throw UsageError("folder " + path.parent_path().string() + " does not exist (a new level is saved there)");
        source = editorSourceFor(path);
    }
    for (const LevelIssue& issue : source.issues)
        std::cerr << issue.format() << "\n"; // opened anyway, with the problems marked

    Campaign campaign;
    try
    {
        campaign = loadCampaignLevels(options.campaignPath, Catalog::builtin());
    }
    catch (const LevelLoadError&)
    {
        // The editor does not need the campaign; the title and level select it leaves to do.
    }
    SaveStore store(defaultDataDirectory());
    // A scripted run never writes the data folder, not even to set a damaged file aside.
    const bool scripted = options.scripted() || !a.window.script.empty();
    store.load(scripted ? SaveStore::Damaged::LeaveAlone : SaveStore::Damaged::SetAside);
    if (!scripted)
        keepSettledLevelsIn((defaultCacheDirectory() / "settled").string());
    pinWindowSettings(a.window, store);
    loadWindowScript(a.window, store, options);
    if (!haveDisplay())
        return kUsageExitCode;
    options.firstScreen = [source = std::move(source)](AppContext& app) -> std::unique_ptr<Screen>
    {
        return std::make_unique<EditorScreen>(app, source);
    };
    useGameScreens(options);
    App app(std::move(options), std::move(campaign), std::move(store), loadGameFont());
    return app.run();
}

} // namespace

CommandRunner addEditCommand(CLI::App& app)
{
    auto args = std::make_shared<EditArgs>();
    CLI::App* cmd = app.add_subcommand(
        "edit", "Open the level editor and sandbox: on LEVEL (created by the first save if it does not exist yet), "
                "or on an empty sandbox scene");
    cmd->add_option("level", args->level, "level JSON file to edit");
    addWindowOptions(*cmd, args->window);
    return [args]
    {
        return runEditCommand(*args);
    };
}

} // namespace abalike::app
