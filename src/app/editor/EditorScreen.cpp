#include "editor/EditorScreen.hpp"

#include "render/Font.hpp"
#include "render/Palette.hpp"
#include "shell/AppContext.hpp"
#include "shell/PlayerSettings.hpp"
#include "shell/RunControl.hpp"
#include "shell/Trace.hpp"
#include "shell/UiMetrics.hpp"

#include <abalike/save/DataDirectory.hpp>
#include <algorithm>
#include <imgui.h>
#include <imgui_internal.h>
#include <iostream>

namespace abalike::app
{

namespace
{
/// imgui.ini lives with the player's other files; scripted runs keep none.
std::string imguiIniPath(const AppContext& app)
{
    if (app.run().scripted())
        return {};
    const auto dir = defaultDataDirectory();
    std::error_code ec;
    if (dir.empty() || !std::filesystem::is_directory(dir, ec))
        return {};
    return (dir / "imgui.ini").string();
}
} // namespace

EditorScreen::EditorScreen(AppContext& app, EditorSource source)
    : m_ctx(app, source), m_imgui(app.ui().window(), imguiIniPath(app), gameFontPath()), m_tools(m_ctx),
      m_drawing(m_ctx, m_tools), m_play(m_ctx), m_clipboard(m_ctx, m_tools), m_files(m_ctx, m_play, m_tools),
      m_inspector(m_ctx, m_play, m_drawing), m_panels(m_ctx, m_tools, m_play, m_files, m_clipboard, m_inspector)
{
    if (source.newFile)
        m_ctx.say("New level: the first save creates " + source.path.string());
    if (!source.issues.empty())
        m_ctx.say(std::to_string(source.issues.size()) + " geometry problem(s) found when opening; marked in red");
    app.trace().write("editor", {{"level", m_ctx.scene().level().id}, {"path", source.path.string()}});
}

EditorScreen::~EditorScreen() = default;

bool EditorScreen::wantsTextInput() const
{
    return m_imgui.wantsText();
}

void EditorScreen::handleEvent(const sf::Event& event)
{
    m_imgui.handleEvent(event);
    if (m_ctx.modalOpen)
        return; // a dialog is up: it takes everything
    switch (event.type)
    {
    case sf::Event::KeyPressed:
    {
        if (m_imgui.wantsText())
            return; // typing into a field
        // A panel has the keys only while it is being driven from the keyboard (Tab, arrows): after a click on a
        // panel, Space and the arrows still aim and nudge in the scene.
        const bool panelFocused =
            ImGui::IsWindowFocused(ImGuiFocusedFlags_AnyWindow) && !ImGui::GetCurrentContext()->NavDisableHighlight;
        if (panelFocused && event.key.code == sf::Keyboard::Escape)
        {
            m_ctx.focusScene = true; // Esc in a panel gives the keys back to the scene
            return;
        }
        if (panelFocused && !event.key.control && event.key.code != sf::Keyboard::F5)
            return; // arrows and letters move through the panel's widgets
        handleKey(event.key);
        return;
    }
    case sf::Event::KeyReleased:
        if (!m_imgui.wantsText())
            m_play.handleSceneEvent(event);
        return;
    case sf::Event::MouseButtonPressed:
    case sf::Event::MouseButtonReleased:
    case sf::Event::MouseMoved:
    case sf::Event::MouseWheelScrolled:
        m_tools.handleMouse(event, m_play);
        return;
    default:
        return;
    }
}

void EditorScreen::fixedUpdate(double dtS)
{
    (void)dtS;
    m_play.fixedUpdate();
}

void EditorScreen::frameUpdate(double frameS)
{
    AppContext& app = m_ctx.app;
    m_imgui.setStyle(app.ui().scale(), app.settings().current().highContrast);
    m_ctx.checks.poll();
    m_files.autosaveIfDue();
    m_drawing.refresh();
    if (!m_ctx.viewFitted)
        m_ctx.fitView();
    // Surfaces pull an object within 12 pixels, never more than 10 cm: near enough to mean it, too near to throw a
    // pig onto the wrong wall.
    m_ctx.scene().snapSettings().surfaceReachM = std::clamp(12.0 / m_ctx.view.pixelsPerMetre(), 0.02, 0.1);
    const bool busy = m_play.playing() || m_tools.handleDragged() || ImGui::IsAnyItemActive();
    m_ctx.checks.recheckAfterEdits(m_ctx.scene(), busy, app.trace());
    m_play.frameUpdate(frameS);
    m_imgui.newFrame(frameS);
    m_panels.build();
}

void EditorScreen::onResize(sf::Vector2u size)
{
    (void)size;
    m_ctx.viewFitted = false;
}

void EditorScreen::draw(sf::RenderTarget& target)
{
    if (m_play.playing())
        m_play.draw(target);
    else
        m_drawing.draw(target);
    m_imgui.render();
}

bool EditorScreen::onCloseRequest()
{
    m_files.request(EditorFiles::Pending::Quit);
    return true;
}

} // namespace abalike::app
