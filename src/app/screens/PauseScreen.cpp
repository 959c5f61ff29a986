#include "screens/PauseScreen.hpp"

#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "screens/HelpScreen.hpp"
#include "screens/Navigation.hpp"
#include "screens/PlayScreen.hpp"
#include "screens/SettingsScreen.hpp"
#include "shell/AppContext.hpp"
#include "shell/Navigator.hpp"
#include "shell/PlayerProgress.hpp"
#include "shell/UiMetrics.hpp"
#include "ui/Card.hpp"

namespace abalike::app
{

PauseScreen::PauseScreen(AppContext& app, PlayScreen& play) : m_app(app), m_play(play)
{
    showMenu(false);
}

void PauseScreen::showMenu(bool confirmQuit)
{
    m_confirmingQuit = confirmQuit;
    if (confirmQuit)
        m_menu.setItems({
            {"keep", "Keep playing", true},
            {"quit-now", "Quit (this try of the level is lost)", true},
        });
    else
        m_menu.setItems({
            {"resume", "Resume", true},
            {"restart", "Restart level", true},
            {"settings", "Settings", true},
            {"help", "Controls", true},
            {"levels", "Level select", !m_app.progress().campaign().levels.empty()},
            {"quit", "Quit game", true},
        });
}

void PauseScreen::handleEvent(const sf::Event& event)
{
    if (event.type == sf::Event::KeyPressed &&
        (event.key.code == sf::Keyboard::Escape || event.key.code == sf::Keyboard::P))
    {
        activate(m_confirmingQuit ? "keep" : "resume");
        return;
    }
    if (m_confirmingQuit)
    {
        if (const std::optional<std::string> id = m_menu.handleEvent(event))
            activate(*id);
        return;
    }
    if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::R)
    {
        activate("restart");
        return;
    }
    if (const std::optional<std::string> id = m_menu.handleEvent(event))
        activate(*id);
}

void PauseScreen::activate(const std::string& id)
{
    if (id == "resume")
        m_app.navigator().screens().pop();
    else if (id == "restart")
    {
        m_play.restartLevel();
        m_app.navigator().screens().pop();
    }
    else if (id == "settings")
        m_app.navigator().screens().push(std::make_unique<SettingsScreen>(m_app));
    else if (id == "help")
        m_app.navigator().screens().push(std::make_unique<HelpScreen>(m_app));
    else if (id == "levels")
        openLevelSelect(m_app);
    else if (id == "quit")
        showMenu(true); // a level is running: ask first
    else if (id == "keep")
        showMenu(false);
    else if (id == "quit-now")
        m_app.navigator().quit(0);
}

void PauseScreen::draw(sf::RenderTarget& target)
{
    drawScrim(target);
    const float scale = m_app.ui().scale();
    const sf::Vector2f window(target.getSize());
    const unsigned titleSize = m_app.ui().textSize(36.0f);
    const unsigned itemSize = m_app.ui().textSize(22.0f);
    const float width = std::min(window.x - 40.0f, 420.0f * scale);
    const float titleHeight = m_app.ui().font() != nullptr ? m_app.ui().font()->getLineSpacing(titleSize) : 0.0f;
    const float itemHeight =
        (m_app.ui().font() != nullptr ? m_app.ui().font()->getLineSpacing(itemSize) : 20.0f) + 22.0f * scale;
    const float height = titleHeight + static_cast<float>(m_menu.items().size()) * itemHeight + 60.0f * scale;
    const sf::FloatRect card(0.5f * (window.x - width), 0.5f * (window.y - height), width, height);
    drawCard(target, card, scale, palette::kButtonOutline);
    float y = card.top + 20.0f * scale;
    if (m_app.ui().font() != nullptr)
        drawLabel(target, *m_app.ui().font(), utf8(m_confirmingQuit ? "Quit the game?" : "Paused"),
                  {card.left + 0.5f * width, y}, titleSize, palette::kText, Align::Centre);
    y += titleHeight + 12.0f * scale;
    m_menu.draw(target, m_app.ui().font(), card.left + 0.5f * width, y, width - 60.0f * scale, itemSize, scale);
}

} // namespace abalike::app
