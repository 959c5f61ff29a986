#include "cli/Arguments.hpp"
#include "cli/Commands.hpp"
#include "cli/GeneratedLevelFile.hpp"
#include "cli/UsageError.hpp"
#include "cli/WindowOptions.hpp"
#include "input/ScriptedInput.hpp"
#include "render/Font.hpp"
#include "screens/GameScreens.hpp"
#include "shell/App.hpp"
#include "shell/DataPaths.hpp"

#include <abalike/level/Campaign.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/level/SafeText.hpp>
#include <abalike/save/DataDirectory.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace abalike::app
{

namespace
{

struct PlayArgs
{
    std::string level;
    std::string pack;
    std::string levelId;
    std::string generated;
    bool endless = false;
    std::optional<std::uint64_t> seed;
    std::vector<std::string> shots;
    WindowArgs window;
};

int runPlayCommand(PlayArgs a)
{
    if (a.endless && (!a.generated.empty() || !a.level.empty() || !a.pack.empty() || !a.levelId.empty()))
        throw UsageError("--endless: the endless mode plays generated levels; give no level, number, pack or "
                         "generated level with it");
    if (a.seed && !a.endless)
        throw UsageError("--seed: the first generated level's seed in the endless mode; give it with --endless");
    if (!a.generated.empty())
    {
        if (!a.level.empty() || !a.pack.empty() || !a.levelId.empty())
            throw UsageError(
                "--generated: give a generated level, a level file, a level number or a pack, one of them");
        a.level = generatedLevelFile(parseGeneratedLevelName(a.generated)).string();
    }
    AppOptions options;
    options.levelPath = a.level;
    options.campaignPath = campaignManifest();
    applyWindowOptions(a.window, options);
    options.endless = a.endless;
    options.endlessSeed = a.seed;
    for (const std::string& text : a.shots)
        options.shots.push_back(parseShot(text));

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

    // Level packs installed in the data folder follow the bundled campaign; one that does not load is skipped
    // with a line saying why, so a broken pack never stops the game.
    std::string packName;
    for (const std::string& folder : installedLevelPacks((defaultDataDirectory() / "packs").string()))
    {
        try
        {
            appendLevelPack(campaign, folder, Catalog::builtin());
        }
        catch (const LevelLoadError& error)
        {
            std::cerr << "abalike: the level pack " << escapeForTerminal(folder) << " does not load, so it is skipped ("
                      << (error.issues().empty() ? error.what() : error.issues().front().format()) << ")\n";
        }
    }
    if (!a.levelId.empty())
    {
        // A campaign level by its number, as its tile and its title show it (a pack's as PACK/NUMBER), for a class
        // told "open 3-2".
        if (!a.level.empty() || !a.pack.empty())
            throw UsageError("--level: give a level number, a level file or a pack, one of them");
        const std::optional<std::size_t> index = campaign.indexOfNumber(a.levelId);
        if (!index)
        {
            std::string numbers;
            for (const std::string& number : campaign.levelArguments())
                numbers += (numbers.empty() ? "" : ", ") + number;
            throw UsageError("--level: no campaign level has the number \"" + a.levelId +
                             "\" (expected one of: " + numbers + ")");
        }
        options.levelPath = campaign.levels[*index].path;
        options.level = campaign.levels[*index].level;
    }
    if (!a.pack.empty())
    {
        if (!a.level.empty())
            throw UsageError("--pack: give a level pack or a level file, not both");
        const std::filesystem::path folder = std::filesystem::absolute(a.pack).lexically_normal();
        packName = (folder.filename().empty() ? folder.parent_path() : folder).filename().string();
        const bool installed = std::any_of(campaign.levels.begin(), campaign.levels.end(),
                                           [&](const CampaignLevel& l) { return l.pack == packName; });
        if (!installed)
        {
            // A pack that `abalike check` fails is not played: the same lines say why.
            const std::filesystem::path manifest = folder / "campaign.json";
            if (std::filesystem::is_regular_file(manifest) && !packPassesCheck(manifest.string(), std::cerr))
                throw UsageError("--pack: " + escapeForTerminal(a.pack) +
                                 " does not pass abalike check (above); fix "
                                 "what it says, then play it");
            appendLevelPack(campaign, a.pack, Catalog::builtin()); // its errors end the command, every one shown
        }
    }

    SaveStore store(defaultDataDirectory());
    // A scripted run never writes the data folder, not even to set a damaged file aside.
    const bool scripted = options.scripted() || !a.window.script.empty();
    store.load(scripted ? SaveStore::Damaged::LeaveAlone : SaveStore::Damaged::SetAside);
    if (!scripted)
        keepSettledLevelsIn((defaultCacheDirectory() / "settled").string());
    pinWindowSettings(a.window, store);
    loadWindowScript(a.window, store, options);
    if (!packName.empty())
    {
        // The pack's first level without a star, or its first level when every one has some.
        std::optional<std::size_t> start;
        for (std::size_t i = 0; i < campaign.levels.size(); ++i)
        {
            if (campaign.levels[i].pack != packName)
                continue;
            if (!start)
                start = i;
            const auto record = store.progress().levels.find(campaign.levels[i].key);
            if (record == store.progress().levels.end() || record->second.stars == 0)
            {
                start = i;
                break;
            }
        }
        options.levelPath = campaign.levels[*start].path;
        options.level = campaign.levels[*start].level;
    }
    if (!haveDisplay())
        return kUsageExitCode;
    useGameScreens(options);
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
    cmd->add_option("--level", args->levelId,
                    "a campaign level by its number, as its tile and title show it (e.g. 3-2: episode 3, second "
                    "level; a pack's as PACK/NUMBER), opened directly even if it is still locked");
    cmd->add_option("--pack", args->pack,
                    "a level pack (a folder with a campaign.json): its episodes follow the campaign's, and play opens "
                    "its first unfinished level");
    cmd->add_option("--generated", args->generated,
                    "SEED[:LOSS_SHARE]: the level `abalike generate --seed SEED --loss-share L` makes (default 0.5), "
                    "generated once and kept in the cache folder");
    cmd->add_flag("--endless", args->endless,
                  "the endless mode: generated castles, harder after a win, easier after a loss (the title's "
                  "\"Endless castles\")");
    cmd->add_option("--seed", args->seed,
                    "with --endless: the seed of the first level generated while playing (default: from the clock)");
    cmd->add_option("--shot", args->shots,
                    "ANGLE,SPEED[,ABILITY_AT_S] to fire when a bird is ready; repeat for more (with no level: the "
                    "campaign's first level)")
        ->allow_extra_args(false);
    addWindowOptions(*cmd, args->window);
    return [args]
    {
        return runPlayCommand(*args);
    };
}

} // namespace abalike::app
