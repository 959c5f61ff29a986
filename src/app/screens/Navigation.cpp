#include "screens/Navigation.hpp"

#include "screens/LevelSelectScreen.hpp"
#include "screens/PlayScreen.hpp"
#include "screens/TitleScreen.hpp"
#include "shell/AppContext.hpp"
#include "shell/Navigator.hpp"
#include "shell/PlayerProgress.hpp"

namespace abalike::app
{

void openTitle(AppContext& app)
{
    app.navigator().screens().clear();
    app.navigator().screens().push(std::make_unique<TitleScreen>(app));
}

void openLevelSelect(AppContext& app)
{
    openTitle(app);
    app.navigator().screens().push(std::make_unique<LevelSelectScreen>(app));
}

std::size_t continueLevel(const AppContext& app)
{
    const Campaign& campaign = app.progress().campaign();
    std::size_t lastUnlocked = 0;
    for (std::size_t i = 0; i < campaign.levels.size(); ++i)
    {
        const std::string& id = campaign.levels[i].key;
        if (!app.progress().isUnlocked(id))
            continue;
        lastUnlocked = i;
        const auto record = app.progress().current().levels.find(id);
        if (record == app.progress().current().levels.end() || record->second.stars == 0)
            return i;
    }
    return lastUnlocked;
}

void playCampaignLevel(AppContext& app, std::size_t index)
{
    const CampaignLevel& level = app.progress().campaign().levels.at(index);
    app.navigator().screens().push(std::make_unique<PlayScreen>(app, PlaySource{level.level, level.path, index}));
}

} // namespace abalike::app
