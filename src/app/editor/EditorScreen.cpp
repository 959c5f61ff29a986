#include "editor/EditorScreen.hpp"

#include "render/Font.hpp"
#include "render/Palette.hpp"
#include "shell/App.hpp"

#include <SFML/Graphics/Sprite.hpp>
#include <abalike/edit/Autosave.hpp>
#include <abalike/save/DataDirectory.hpp>
#include <box2d/box2d.h>
#include <imgui.h>
#include <imgui_internal.h>
#include <iostream>

namespace abalike::app
{

namespace
{
/// imgui.ini lives with the player's other files; scripted runs keep none.
std::string imguiIniPath(const App& app)
{
    if (app.scripted())
        return {};
    const auto dir = defaultDataDirectory();
    std::error_code ec;
    if (dir.empty() || !std::filesystem::is_directory(dir, ec))
        return {};
    return (dir / "imgui.ini").string();
}
} // namespace

EditorScreen::EditorScreen(App& app, EditorSource source)
    : m_app(app), m_imgui(app.window(), imguiIniPath(app), gameFontPath()),
      m_editor(std::make_unique<SceneEditor>(source.level))
{
    m_editor->setPath(source.path);
    if (source.newFile)
        m_message = "New level: the first save creates " + source.path.string();
    m_checks.setOpeningIssues(source.issues, m_editor->revision());
    if (!source.issues.empty())
        m_message = std::to_string(source.issues.size()) + " geometry problem(s) found when opening; marked in red";
    m_app.trace().write("editor", {{"level", m_editor->level().id}, {"path", source.path.string()}});
    // An unsaved scene from a run that ended without saving is offered back (never in scripted runs).
    if (!m_app.scripted())
    {
        const auto dir = defaultDataDirectory();
        try
        {
            if (auto saved = dir.empty() ? std::nullopt : readAutosave(autosavePath(dir), Catalog::builtin()))
            {
                EditorSource recovered;
                recovered.level = std::move(saved->level);
                recovered.path = saved->target;
                recovered.issues = std::move(saved->geometryIssues);
                m_recovered = std::move(recovered);
            }
        }
        catch (const LevelLoadError& error)
        {
            std::cerr << "abalike: " << error.what() << "\n";
        }
    }
}

EditorScreen::~EditorScreen() = default;

bool EditorScreen::wantsTextInput() const
{
    return m_imgui.wantsText();
}

sf::FloatRect EditorScreen::sceneArea() const
{
    const sf::Vector2f size(m_app.windowSize());
    const float scale = m_app.uiScale();
    // The menu bar and the status bar: a line of 16 px text with ImGui's frame and window padding.
    const float top = 22.0f * scale;
    const float bottom = playing() ? 0.0f : 38.0f * scale;
    const float left = playing() ? 0.0f : 220.0f * scale;
    const float right = 350.0f * scale;
    return {left, top, std::max(50.0f, size.x - left - right), std::max(50.0f, size.y - top - bottom)};
}

void EditorScreen::fitView()
{
    m_view.fit(m_editor->level(), Catalog::builtin(), sceneArea(), m_app.windowSize());
    m_viewFitted = true;
}

bool EditorScreen::pointerOverPanels(sf::Vector2f pixel) const
{
    for (const sf::FloatRect& panel : m_panels)
        if (panel.contains(pixel))
            return true;
    return false;
}

void EditorScreen::refreshScene()
{
    if (m_scene && m_sceneRevision == m_editor->revision())
        return;
    m_sceneRevision = m_editor->revision();
    try
    {
        m_scene = std::make_unique<GameSession>(m_editor->level(), Catalog::builtin());
        m_sceneError.clear();
    }
    catch (const std::exception& error)
    {
        m_sceneError = error.what(); // the model keeps the level loadable; say so if it ever is not
    }
}

void EditorScreen::startPlay()
{
    if (playing())
        return;
    m_editor->endDrag();
    m_play = std::make_unique<ScenePlay>(m_app, m_editor->level(), playCamera());
    m_play->aimAt(m_playAngleDeg, std::min(m_playSpeedMps, m_play->maxSpeedMps()));
    m_app.trace().write("editor-play", {{"level", m_editor->level().id}});
    m_message = "Drag the bird back, or set the angle and speed here and Fire. Esc returns to the scene as it was.";
    m_messageIsError = false;
}

Camera EditorScreen::playCamera() const
{
    const sf::FloatRect area = sceneArea();
    return Camera::fromView(m_view.toWorld({area.left, area.top}), m_view.pixelsPerMetre(),
                            {static_cast<unsigned>(area.width), static_cast<unsigned>(area.height)});
}

void EditorScreen::followBirdInPlay()
{
    const GameSession& session = m_play->session();
    const Entity* bird = session.world().bird();
    if (bird == nullptr || bird->body == nullptr || session.phase() == Phase::Aiming)
        return;
    // Pan when the bird comes within 60 px of the play area's edge, so that it stays at least that far in.
    const Camera camera = playCamera();
    const b2Vec2 position = bird->body->GetPosition();
    const sf::Vector2f at = camera.toScreen({position.x, position.y});
    const sf::Vector2f size(camera.windowSize());
    const float margin = std::min(60.0f * m_app.uiScale(), 0.25f * std::min(size.x, size.y));
    sf::Vector2f shift(0.0f, 0.0f);
    if (at.x > size.x - margin)
        shift.x = size.x - margin - at.x;
    else if (at.x < margin)
        shift.x = margin - at.x;
    if (at.y < margin)
        shift.y = margin - at.y;
    else if (at.y > size.y - margin)
        shift.y = size.y - margin - at.y;
    if (shift.x != 0.0f || shift.y != 0.0f)
        m_view.pan(shift);
}

void EditorScreen::stopPlay()
{
    if (!playing())
        return;
    m_play.reset();
    m_app.trace().write("editor-edit", {{"level", m_editor->level().id}});
    m_message = "Back to the scene as it was before the shot.";
    m_messageIsError = false;
}

void EditorScreen::syncPlay()
{
    // The environment and the custom bird are live while the scene plays.
    if (!playing())
        return;
    m_play->setEnvironment(m_editor->level().environment);
    if (m_editor->level().customBird)
        m_play->setCustomBird(*m_editor->level().customBird);
}

void EditorScreen::handleEvent(const sf::Event& event)
{
    m_imgui.handleEvent(event);
    if (m_modalOpen)
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
            m_focusScene = true; // Esc in a panel gives the keys back to the scene
            return;
        }
        if (panelFocused && !event.key.control && event.key.code != sf::Keyboard::F5)
            return; // arrows and letters move through the panel's widgets
        handleKey(event.key);
        return;
    }
    case sf::Event::KeyReleased:
        if (playing() && !m_imgui.wantsText())
            m_play->handleEvent(event);
        return;
    case sf::Event::MouseButtonPressed:
    case sf::Event::MouseButtonReleased:
    case sf::Event::MouseMoved:
    case sf::Event::MouseWheelScrolled:
        handleSceneMouse(event);
        return;
    default:
        return;
    }
}

void EditorScreen::handleKey(const sf::Event::KeyEvent& key)
{
    using K = sf::Keyboard;
    if (key.code == K::F5)
    {
        playing() ? stopPlay() : startPlay();
        return;
    }
    if (playing())
    {
        if (key.code == K::Escape)
            stopPlay();
        else if (key.code == K::P)
            m_play->setFrozen(!m_play->frozen()); // paused or running, the panels stay live
        else
        {
            sf::Event event;
            event.type = sf::Event::KeyPressed;
            event.key = key;
            m_play->handleEvent(event);
        }
        return;
    }
    const double step = key.shift ? 0.01 : (m_editor->snapSettings().grid ? m_editor->snapSettings().gridM : 0.05);
    if (key.control)
    {
        switch (key.code)
        {
        case K::Z:
            key.shift ? m_editor->redo() : m_editor->undo();
            break;
        case K::Y:
            m_editor->redo();
            break;
        case K::S:
            if (key.shift)
            {
                m_fileDialogSaves = true;
                m_fileDialogPath = defaultSavePath().string();
                m_showFileDialog = true;
            }
            else
                requestSave();
            break;
        case K::O:
            request(Pending::Open);
            break;
        case K::N:
            request(Pending::New);
            break;
        case K::C:
            copySelection(false);
            break;
        case K::X:
            copySelection(true);
            break;
        case K::V:
            pasteClipboard();
            break;
        case K::D:
            m_editor->duplicateSelection();
            break;
        case K::M:
            m_editor->mirrorSelection();
            break;
        case K::A:
            m_editor->selectAll();
            break;
        default:
            break;
        }
        return;
    }
    switch (key.code)
    {
    case K::Escape:
        if (m_tool != Tool::Select)
            m_tool = Tool::Select;
        else if (!m_editor->selection().empty())
            m_editor->clearSelection();
        else
            request(Pending::Leave);
        break;
    case K::Delete:
    case K::BackSpace:
        m_editor->deleteSelection();
        break;
    case K::Left:
        m_editor->moveSelection(-step, 0.0);
        break;
    case K::Right:
        m_editor->moveSelection(step, 0.0);
        break;
    case K::Up:
        m_editor->moveSelection(0.0, step);
        break;
    case K::Down:
        m_editor->moveSelection(0.0, -step);
        break;
    case K::Q:
        m_editor->rotateSelection(key.shift ? 1.0 : m_editor->snapSettings().rotationStepDeg);
        break;
    case K::E:
        m_editor->rotateSelection(key.shift ? -1.0 : -m_editor->snapSettings().rotationStepDeg);
        break;
    case K::LBracket:
    case K::RBracket:
        if (m_editor->selection().size() == 1)
        {
            const ObjectRef ref = m_editor->selection()[0];
            const ObjectDef def = objectDef(m_editor->level(), ref);
            double w = 0.0;
            double h = 0.0;
            if (const auto* b = std::get_if<BlockDef>(&def))
                std::tie(w, h) = std::pair(b->widthM, b->heightM);
            else if (const auto* t = std::get_if<TerrainDef>(&def))
                std::tie(w, h) = std::pair(t->widthM, t->heightM);
            // One rule for both: the grid step (0.05 m with the grid off); Shift chooses the height, not the step.
            const double resizeStep = m_editor->snapSettings().grid ? m_editor->snapSettings().gridM : 0.05;
            const double change = (key.code == K::RBracket ? 1.0 : -1.0) * resizeStep;
            if (w > 0.0)
            {
                const std::string why =
                    key.shift ? m_editor->resizeObject(ref, w, h + change) : m_editor->resizeObject(ref, w + change, h);
                if (!why.empty())
                {
                    m_message = why;
                    m_messageIsError = true;
                }
            }
        }
        break;
    case K::V:
        m_tool = Tool::Select;
        break;
    case K::B:
        m_tool = Tool::Block;
        break;
    case K::P:
        m_tool = Tool::Pig;
        break;
    case K::T:
        m_tool = Tool::Terrain;
        m_terrainTemplate = TerrainDef{0.0, 0.0, 4.0, 1.0, 0.0, {}};
        break;
    case K::H:
        chooseHillTool();
        break;
    case K::L:
        m_tool = Tool::Slingshot;
        break;
    case K::G:
        m_editor->snapSettings().grid = !m_editor->snapSettings().grid;
        break;
    case K::M:
        m_editor->snapSettings().surfaces = !m_editor->snapSettings().surfaces;
        break;
    case K::F:
    case K::Home:
        fitView();
        break;
    default:
        break;
    }
    m_editor->endGesture(); // each key press is its own undo step
}

void EditorScreen::fixedUpdate(double dtS)
{
    (void)dtS;
    if (playing())
        m_play->fixedUpdate();
}

void EditorScreen::frameUpdate(double frameS)
{
    m_imgui.setStyle(m_app.uiScale(), m_app.settings().highContrast);
    m_checks.poll();
    autosaveIfDue();
    refreshScene();
    if (!m_viewFitted)
        fitView();
    // Surfaces pull an object within 12 pixels, never more than 10 cm: near enough to mean it, too near to throw a
    // pig onto the wrong wall.
    m_editor->snapSettings().surfaceReachM = std::clamp(12.0 / m_view.pixelsPerMetre(), 0.02, 0.1);
    recheckAfterEdits();
    if (playing())
    {
        followBirdInPlay();
        m_play->setCamera(playCamera());
        m_play->frameUpdate(frameS);
    }
    m_imgui.newFrame(frameS);
    buildUi();
}

void EditorScreen::onResize(sf::Vector2u size)
{
    (void)size;
    m_viewFitted = false;
}

void EditorScreen::draw(sf::RenderTarget& target)
{
    if (playing())
    {
        // The play test fills the free part of the window exactly; the panels sit beside it, not over it.
        const sf::FloatRect area = sceneArea();
        const sf::Vector2u size(static_cast<unsigned>(area.width), static_cast<unsigned>(area.height));
        if (m_playTexture.getSize() != size)
            (void)m_playTexture.create(size.x, size.y);
        m_playTexture.clear();
        m_play->draw(m_playTexture);
        m_playTexture.display();
        sf::Sprite sprite(m_playTexture.getTexture());
        sprite.setPosition(area.left, area.top);
        target.draw(sprite);
    }
    else if (m_scene)
    {
        const Camera camera = m_view.camera(target.getSize());
        m_renderer.drawBackground(target, camera, *m_scene);
        m_renderer.drawForeground(target, camera, *m_scene, {0.0f, 0.0f});
        drawOverlay(target);
    }
    m_imgui.render();
}

bool EditorScreen::onCloseRequest()
{
    request(Pending::Quit);
    return true;
}

} // namespace abalike::app
