#include "screens/TitleScreen.hpp"

#include "editor/EditorSource.hpp"
#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "render/TitleArt.hpp"
#include "screens/EndlessNavigation.hpp"
#include "screens/HelpScreen.hpp"
#include "screens/LearnScreen.hpp"
#include "screens/LevelSelectScreen.hpp"
#include "screens/Navigation.hpp"
#include "screens/SettingsScreen.hpp"
#include "shell/AppContext.hpp"
#include "shell/Navigator.hpp"
#include "shell/PlayerProgress.hpp"
#include "shell/PlayerSettings.hpp"
#include "shell/UiMetrics.hpp"
#include "ui/Card.hpp"

namespace abalike::app
{

namespace
{
LevelDef sceneryLevel(const AppContext& app)
{
    if (!app.progress().campaign().levels.empty())
        return app.progress().campaign().levels.front().level;
    LevelDef empty;
    empty.id = "title";
    return empty;
}
} // namespace

TitleScreen::TitleScreen(AppContext& app)
    : m_app(app), m_scenery(std::make_unique<GameSession>(sceneryLevel(app), Catalog::builtin())),
      m_camera(Camera::fitLevel(m_scenery->level(), Catalog::builtin(), app.ui().windowSize()))
{
    const bool hasCampaign = !app.progress().campaign().levels.empty();
    const bool started =
        hasCampaign && app.progress().current().levels.count(app.progress().campaign().levels.front().key) > 0;
    m_menu.setItems({
        {"play", started ? "Play: continue" : "Play", hasCampaign},
        {"levels", "Level select", hasCampaign},
        {"endless", "Endless castles", true},
        {"learn", "Learn: lessons, tutorial, physics", true},
        {"sandbox", "Sandbox and editor", true},
        {"settings", "Settings", true},
        {"help", "Controls", true},
        {"quit", "Quit", true},
    });
}

void TitleScreen::handleEvent(const sf::Event& event)
{
    if (const std::optional<std::string> id = m_menu.handleEvent(event))
        activate(*id);
}

void TitleScreen::activate(const std::string& id)
{
    if (id == "play")
    {
        m_app.settings().setMode(PlayMode::Game);
        playCampaignLevel(m_app, continueLevel(m_app));
    }
    else if (id == "endless")
    {
        m_app.settings().setMode(PlayMode::Game);
        m_app.navigator().screens().push(nextEndlessScreen(m_app));
    }
    else if (id == "levels")
        m_app.navigator().screens().push(std::make_unique<LevelSelectScreen>(m_app));
    else if (id == "learn")
        m_app.navigator().screens().push(std::make_unique<LearnScreen>(m_app));
    else if (id == "sandbox")
        openEditor(m_app, sandboxSource());
    else if (id == "settings")
        m_app.navigator().screens().push(std::make_unique<SettingsScreen>(m_app));
    else if (id == "help")
        m_app.navigator().screens().push(std::make_unique<HelpScreen>(m_app));
    else if (id == "quit")
        m_app.navigator().quit(0);
}

void TitleScreen::onResize(sf::Vector2u size)
{
    m_camera = Camera::fitLevel(m_scenery->level(), Catalog::builtin(), size);
}

void TitleScreen::draw(sf::RenderTarget& target)
{
    m_world.drawBackground(target, m_camera, *m_scenery);
    m_world.drawForeground(target, m_camera, *m_scenery, {0.0f, 0.0f});
    drawScrim(target);
    drawTitleArt(target, m_app.ui().scale());

    const float scale = m_app.ui().scale();
    const sf::Vector2f window(target.getSize());
    const float centre = 0.5f * window.x;
    float y = 0.12f * window.y;
    if (const sf::Font* font = m_app.ui().font())
    {
        const unsigned titleSize = m_app.ui().textSize(64.0f);
        const unsigned subtitleSize = m_app.ui().textSize(22.0f);
        drawLabel(target, *font, utf8("Angry Birds Alike"), {centre, y}, titleSize, palette::kStar, Align::Centre);
        y += font->getLineSpacing(titleSize);
        drawLabel(target, *font, utf8("A slingshot physics game, and a physics lesson"), {centre, y}, subtitleSize,
                  palette::kText, Align::Centre);
        y += font->getLineSpacing(subtitleSize) + 30.0f * scale;
    }
    m_menu.draw(target, m_app.ui().font(), centre, y, std::min(window.x - 40.0f, 360.0f * scale),
                m_app.ui().textSize(24.0f), scale);
    if (const sf::Font* font = m_app.ui().font())
    {
        const unsigned hintSize = m_app.ui().textSize(16.0f);
        drawLabel(target, *font, utf8("F1 or ?: controls   \u00B7   arrows and Enter, or the mouse"),
                  {centre, window.y - 36.0f * scale}, hintSize, palette::kText, Align::Centre);
    }
}

} // namespace abalike::app
