#include "screens/GameScreens.hpp"

#include "screens/EndlessNavigation.hpp"

#include "screens/HelpScreen.hpp"
#include "screens/PlayScreen.hpp"
#include "screens/TitleScreen.hpp"
#include "shell/AppContext.hpp"
#include "shell/PlayerProgress.hpp"
#include "shell/RunControl.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>

namespace abalike::app
{

namespace
{

/// Whether a level file given on the command line is this campaign level: the same file, or a copy with the same
/// bytes (a build tree plays the staged copy of levels/, while designers name the source file).
bool sameLevelFile(const std::string& campaignPath, const std::string& givenPath)
{
    std::error_code ec;
    if (std::filesystem::equivalent(campaignPath, givenPath, ec))
        return true;
    const auto size = std::filesystem::file_size(campaignPath, ec);
    if (ec || size != std::filesystem::file_size(givenPath, ec) || ec)
        return false;
    std::ifstream a(campaignPath, std::ios::binary);
    std::ifstream b(givenPath, std::ios::binary);
    return std::equal(std::istreambuf_iterator<char>(a), {}, std::istreambuf_iterator<char>(b), {});
}

} // namespace

std::unique_ptr<Screen> openingScreen(AppContext& app)
{
    const AppOptions& options = app.run().options();
    const Campaign& campaign = app.progress().campaign();
    if (options.endless)
        return nextEndlessScreen(app);
    if (options.level)
    {
        // A level given on the command line: straight into it. If it is a campaign level, "next" follows the
        // campaign from there.
        std::optional<std::size_t> index;
        for (std::size_t i = 0; i < campaign.levels.size() && !index; ++i)
            if (sameLevelFile(campaign.levels[i].path, options.levelPath))
                index = i;
        return std::make_unique<PlayScreen>(app, PlaySource{*options.level, options.levelPath, index});
    }
    if (!options.shots.empty() && !campaign.levels.empty())
    {
        // Scripted shots without a level start the campaign's first level, as they always have.
        const CampaignLevel& first = campaign.levels.front();
        return std::make_unique<PlayScreen>(app, PlaySource{first.level, first.path, 0});
    }
    return std::make_unique<TitleScreen>(app);
}

void useGameScreens(AppOptions& options)
{
    if (!options.firstScreen)
        options.firstScreen = openingScreen;
    options.helpScreen = [](AppContext& app) -> std::unique_ptr<Screen>
    {
        return std::make_unique<HelpScreen>(app);
    };
}

} // namespace abalike::app
