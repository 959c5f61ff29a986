#include "screens/Navigation.hpp"

#include "screens/LevelSelectScreen.hpp"
#include "screens/PlayScreen.hpp"
#include "screens/TitleScreen.hpp"
#include "shell/App.hpp"

namespace abalike::app
{

void openTitle(App& app)
{
    app.screens().clear();
    app.screens().push(std::make_unique<TitleScreen>(app));
}

void openLevelSelect(App& app)
{
    openTitle(app);
    app.screens().push(std::make_unique<LevelSelectScreen>(app));
}

std::size_t continueLevel(const App& app)
{
    const Campaign& campaign = app.campaign();
    std::size_t lastUnlocked = 0;
    for (std::size_t i = 0; i < campaign.levels.size(); ++i)
    {
        const std::string& id = campaign.levels[i].key;
        if (!app.isUnlocked(id))
            continue;
        lastUnlocked = i;
        const auto record = app.progress().levels.find(id);
        if (record == app.progress().levels.end() || record->second.stars == 0)
            return i;
    }
    return lastUnlocked;
}

void playCampaignLevel(App& app, std::size_t index)
{
    const CampaignLevel& level = app.campaign().levels.at(index);
    app.screens().push(std::make_unique<PlayScreen>(app, PlaySource{level.level, level.path, index}));
}

} // namespace abalike::app
