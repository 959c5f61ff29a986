#include "screens/LearnScreen.hpp"

#include "screens/LessonSelectScreen.hpp"
#include "screens/MenuBackdrop.hpp"
#include "screens/Navigation.hpp"
#include "shell/AppContext.hpp"
#include "shell/Navigator.hpp"
#include "shell/PlayerProgress.hpp"
#include "shell/PlayerSettings.hpp"
#include "shell/UiMetrics.hpp"
#include "teach/Guide.hpp"

#include <algorithm>

namespace abalike::app
{

LearnScreen::LearnScreen(AppContext& app) : m_app(app)
{
    const bool hasCampaign = !app.progress().campaign().levels.empty();
    m_menu.setItems({
        {"campaign", "The campaign, with its physics", hasCampaign},
        {"tutorial",
         app.progress().current().levels.contains(kTutorialId) ? "Tutorial (done; play it again)"
                                                               : "Tutorial: start here",
         true},
        {"lessons", "Lessons", true},
        {"back", "Back", true},
    });
}

void LearnScreen::handleEvent(const sf::Event& event)
{
    if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::Escape)
    {
        m_app.navigator().screens().pop();
        return;
    }
    if (const std::optional<std::string> id = m_menu.handleEvent(event))
        activate(*id);
}

void LearnScreen::activate(const std::string& id)
{
    if (id == "campaign")
    {
        m_app.settings().setMode(PlayMode::Learn);
        playCampaignLevel(m_app, continueLevel(m_app));
    }
    else if (id == "tutorial")
        playTutorial(m_app);
    else if (id == "lessons")
        m_app.navigator().screens().push(std::make_unique<LessonSelectScreen>(m_app));
    else if (id == "back")
        m_app.navigator().screens().pop();
}

void LearnScreen::draw(sf::RenderTarget& target)
{
    const float y = drawMenuBackdrop(
        target, m_app, "Learn",
        "The same game with its physics shown: the full path, the numbers, a sentence after every shot", 0.08f);
    const float scale = m_app.ui().scale();
    const float width = static_cast<float>(target.getSize().x);
    m_menu.draw(target, m_app.ui().font(), 0.5f * width, y, std::min(width - 40.0f, 420.0f * scale),
                m_app.ui().textSize(21.0f), scale);
}

} // namespace abalike::app
