// The editor's keyboard shortcuts (the help screen and the palette list them).
#include "editor/EditorScreen.hpp"

#include <tuple>

namespace abalike::app
{

void EditorScreen::handleKey(const sf::Event::KeyEvent& key)
{
    using K = sf::Keyboard;
    if (key.code == K::F5)
    {
        m_play.playing() ? m_play.stop() : m_play.start();
        return;
    }
    if (m_play.playing())
    {
        if (key.code == K::Escape)
            m_play.stop();
        else if (key.code == K::P)
            m_play.togglePause(); // paused or running, the panels stay live
        else
        {
            sf::Event event;
            event.type = sf::Event::KeyPressed;
            event.key = key;
            m_play.handleSceneEvent(event);
        }
        return;
    }
    const double step =
        key.shift ? 0.01 : (m_ctx.scene().snapSettings().grid ? m_ctx.scene().snapSettings().gridM : 0.05);
    if (key.control)
    {
        handleCommandKey(key);
        return;
    }
    switch (key.code)
    {
    case K::Escape:
        if (m_tools.tool != SceneTools::Tool::Select)
            m_tools.reset(); // and drops what the drop tool held
        else if (!m_ctx.scene().selection().empty())
            m_ctx.scene().clearSelection();
        else
            m_files.request(EditorFiles::Pending::Leave);
        break;
    case K::Delete:
    case K::BackSpace:
        m_ctx.scene().deleteSelection();
        break;
    case K::Left:
        m_ctx.scene().moveSelection(-step, 0.0);
        break;
    case K::Right:
        m_ctx.scene().moveSelection(step, 0.0);
        break;
    case K::Up:
        m_ctx.scene().moveSelection(0.0, step);
        break;
    case K::Down:
        m_ctx.scene().moveSelection(0.0, -step);
        break;
    case K::Q:
        m_ctx.scene().rotateSelection(key.shift ? 1.0 : m_ctx.scene().snapSettings().rotationStepDeg);
        break;
    case K::E:
        m_ctx.scene().rotateSelection(key.shift ? -1.0 : -m_ctx.scene().snapSettings().rotationStepDeg);
        break;
    case K::LBracket:
    case K::RBracket:
        resizeByKey(key);
        break;
    case K::V:
        m_tools.tool = SceneTools::Tool::Select;
        break;
    case K::B:
        m_tools.tool = SceneTools::Tool::Block;
        break;
    case K::P:
        m_tools.tool = SceneTools::Tool::Pig;
        break;
    case K::T:
        m_tools.chooseTerrainBox();
        break;
    case K::H:
        m_tools.chooseHill();
        break;
    case K::L:
        m_tools.tool = SceneTools::Tool::Slingshot;
        break;
    case K::G:
        m_ctx.scene().snapSettings().grid = !m_ctx.scene().snapSettings().grid;
        break;
    case K::M:
        m_ctx.scene().snapSettings().surfaces = !m_ctx.scene().snapSettings().surfaces;
        break;
    case K::F:
    case K::Home:
        m_ctx.fitView();
        break;
    default:
        break;
    }
    m_ctx.scene().endGesture(); // each key press is its own undo step
}

void EditorScreen::handleCommandKey(const sf::Event::KeyEvent& key)
{
    using K = sf::Keyboard;
    switch (key.code)
    {
    case K::Z:
        key.shift ? m_ctx.redo() : m_ctx.undo();
        break;
    case K::Y:
        m_ctx.redo();
        break;
    case K::S:
        key.shift ? m_files.requestSaveAs() : m_files.requestSave();
        break;
    case K::O:
        m_files.request(EditorFiles::Pending::Open);
        break;
    case K::N:
        m_files.request(EditorFiles::Pending::New);
        break;
    case K::C:
        m_clipboard.copySelection(false);
        break;
    case K::X:
        m_clipboard.copySelection(true);
        break;
    case K::V:
        m_clipboard.paste();
        break;
    case K::D:
        m_ctx.scene().duplicateSelection();
        break;
    case K::M:
        m_ctx.scene().mirrorSelection();
        break;
    case K::A:
        m_ctx.scene().selectAll();
        break;
    default:
        break;
    }
}

void EditorScreen::resizeByKey(const sf::Event::KeyEvent& key)
{
    using K = sf::Keyboard;
    if (m_ctx.scene().selection().size() == 1)
    {
        const ObjectRef ref = m_ctx.scene().selection()[0];
        const ObjectDef def = objectDef(m_ctx.scene().level(), ref);
        double w = 0.0;
        double h = 0.0;
        if (const auto* b = std::get_if<BlockDef>(&def))
            std::tie(w, h) = std::pair(b->widthM, b->heightM);
        else if (const auto* t = std::get_if<TerrainDef>(&def))
            std::tie(w, h) = std::pair(t->widthM, t->heightM);
        // One rule for both: the grid step (0.05 m with the grid off); Shift chooses the height, not the step.
        const double resizeStep = m_ctx.scene().snapSettings().grid ? m_ctx.scene().snapSettings().gridM : 0.05;
        const double change = (key.code == K::RBracket ? 1.0 : -1.0) * resizeStep;
        if (w > 0.0)
        {
            const std::string why = key.shift ? m_ctx.scene().resizeObject(ref, w, h + change)
                                              : m_ctx.scene().resizeObject(ref, w + change, h);
            if (!why.empty())
            {
                m_ctx.message = why;
                m_ctx.messageIsError = true;
            }
        }
    }
}

} // namespace abalike::app
