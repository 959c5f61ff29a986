#include "editor/SceneTools.hpp"

#include "editor/EditorContext.hpp"
#include "editor/PlayTest.hpp"
#include "shell/AppContext.hpp"
#include "shell/RunControl.hpp"
#include "shell/Trace.hpp"
#include "shell/UiMetrics.hpp"

#include <abalike/edit/Snapping.hpp>
#include <abalike/util/Angles.hpp>
#include <cmath>
#include <imgui.h>
#include <utility>

namespace abalike::app
{

namespace
{
constexpr float kZoomStep = 1.15f;
constexpr float kHandlePx = 9.0f; ///< half the size of a resize handle

sf::Vector2f pixelOf(const sf::Event& event)
{
    switch (event.type)
    {
    case sf::Event::MouseMoved:
        return {static_cast<float>(event.mouseMove.x), static_cast<float>(event.mouseMove.y)};
    case sf::Event::MouseWheelScrolled:
        return {static_cast<float>(event.mouseWheelScroll.x), static_cast<float>(event.mouseWheelScroll.y)};
    default:
        return {static_cast<float>(event.mouseButton.x), static_cast<float>(event.mouseButton.y)};
    }
}

/// The top-right corner of a block or terrain piece in its own frame, where its resize handle is (m).
std::optional<sf::Vector2f> handleCorner(const ObjectDef& def)
{
    double x = 0.0, y = 0.0, w = 0.0, h = 0.0, a = 0.0;
    if (const auto* b = std::get_if<BlockDef>(&def))
    {
        x = b->x;
        y = b->y;
        w = b->widthM;
        h = b->heightM;
        a = b->angleDeg;
    }
    else if (const auto* t = std::get_if<TerrainDef>(&def))
    {
        x = t->x;
        y = t->y;
        w = t->widthM;
        h = t->heightM;
        a = t->angleDeg;
    }
    else
        return std::nullopt;
    const double c = std::cos(a * kDegToRad);
    const double s = std::sin(a * kDegToRad);
    return sf::Vector2f(static_cast<float>(x + c * w / 2 - s * h / 2), static_cast<float>(y + s * w / 2 + c * h / 2));
}
} // namespace

std::optional<ObjectRef> SceneTools::resizeHandleAt(sf::Vector2f pixel) const
{
    if (m_ctx.scene().selection().size() != 1)
        return std::nullopt;
    const ObjectRef ref = m_ctx.scene().selection()[0];
    if (ref.kind == ObjectKind::Terrain && m_ctx.scene().level().terrain[ref.index].isPolygon())
        return std::nullopt; // its corners have their own handles
    const auto corner = handleCorner(objectDef(m_ctx.scene().level(), ref));
    if (!corner)
        return std::nullopt;
    const sf::Vector2f at = m_ctx.view.camera(m_ctx.app.ui().windowSize()).toScreen(*corner);
    const float reach = (kHandlePx + 3.0f) * m_ctx.app.ui().scale();
    if (std::abs(at.x - pixel.x) <= reach && std::abs(at.y - pixel.y) <= reach)
        return ref;
    return std::nullopt;
}

std::vector<SceneTools::VertexHandle> SceneTools::vertexHandles() const
{
    std::vector<VertexHandle> handles;
    if (m_ctx.scene().selection().size() != 1 || tool != Tool::Select)
        return handles;
    const ObjectRef ref = m_ctx.scene().selection()[0];
    if (ref.kind != ObjectKind::Terrain || !m_ctx.scene().level().terrain[ref.index].isPolygon())
        return handles;
    const std::size_t corners = m_ctx.scene().level().terrain[ref.index].points.size();
    for (std::size_t i = 0; i < corners; ++i)
    {
        handles.push_back({ref.index, i, false});
        handles.push_back({ref.index, i, true});
    }
    return handles;
}

sf::Vector2f SceneTools::vertexHandlePosition(const VertexHandle& handle) const
{
    const auto& points = m_ctx.scene().level().terrain[handle.terrain].points;
    const auto& a = points[handle.vertex];
    if (!handle.edgeMiddle)
        return {static_cast<float>(a.x), static_cast<float>(a.y)};
    const auto& b = points[(handle.vertex + 1) % points.size()];
    return {static_cast<float>(0.5 * (a.x + b.x)), static_cast<float>(0.5 * (a.y + b.y))};
}

std::optional<SceneTools::VertexHandle> SceneTools::vertexHandleAt(sf::Vector2f pixel) const
{
    const Camera camera = m_ctx.view.camera(m_ctx.app.ui().windowSize());
    const float reach = (kHandlePx + 3.0f) * m_ctx.app.ui().scale();
    std::optional<VertexHandle> best;
    float bestDistance = reach;
    for (const VertexHandle& handle : vertexHandles())
    {
        const sf::Vector2f at = camera.toScreen(vertexHandlePosition(handle));
        // Corners win over edge middles at the same distance: they are what a designer grabs most.
        const float distance = std::hypot(at.x - pixel.x, at.y - pixel.y) + (handle.edgeMiddle ? 0.5f : 0.0f);
        if (distance <= bestDistance)
        {
            bestDistance = distance;
            best = handle;
        }
    }
    return best;
}

void SceneTools::pressVertexHandle(const VertexHandle& handle, bool ctrl)
{
    std::string why;
    if (handle.edgeMiddle)
    {
        // A new corner in the edge's middle, at once dragged.
        why = m_ctx.scene().insertVertex(handle.terrain, handle.vertex);
        if (why.empty())
            m_vertexDrag = VertexHandle{handle.terrain, handle.vertex + 1, false};
    }
    else if (ctrl)
        why = m_ctx.scene().removeVertex(handle.terrain, handle.vertex);
    else
        m_vertexDrag = handle;
    m_ctx.message = why;
    m_ctx.messageIsError = !why.empty();
}

ObjectDef SceneTools::toolObject(sf::Vector2f world) const
{
    switch (tool)
    {
    case Tool::Block:
        return withCentre(blockTemplate, world.x, world.y);
    case Tool::Pig:
        return withCentre(pigTemplate, world.x, world.y);
    case Tool::Terrain:
        return withCentre(terrainTemplate, world.x, world.y);
    case Tool::Slingshot:
    {
        SlingshotDef sling = m_ctx.scene().level().slingshot;
        sling.x = world.x;
        sling.y = world.y;
        return sling;
    }
    case Tool::Select:
    case Tool::Drop:
        break;
    }
    return blockTemplate;
}

void SceneTools::handleMouse(const sf::Event& event, PlayTest& play)
{
    const sf::Vector2f pixel = pixelOf(event);
    pointer = pixel;
    const bool busy = m_dragFrom || bandFrom || m_panFrom || m_resizing || m_vertexDrag;
    // A field being typed in keeps the pointer's moves, but not a press on the scene: that click both ends the typing
    // (Dear ImGui commits the field) and does what it does on the scene, so no first click is lost.
    const bool overPanels =
        m_ctx.pointerOverPanels(pixel) || (ImGui::IsAnyItemActive() && event.type != sf::Event::MouseButtonPressed);
    pointerOnScene = !overPanels;
    if (overPanels && !busy)
        return;

    if (event.type == sf::Event::MouseWheelScrolled)
    {
        m_ctx.view.zoomAt(pixel, std::pow(kZoomStep, event.mouseWheelScroll.delta));
        return;
    }
    // Panning is the same in both modes: the right or middle button.
    if (event.type == sf::Event::MouseButtonPressed &&
        (event.mouseButton.button == sf::Mouse::Right || event.mouseButton.button == sf::Mouse::Middle))
    {
        m_panFrom = pixel;
        return;
    }
    if (m_panFrom)
    {
        if (event.type == sf::Event::MouseMoved)
        {
            m_ctx.view.pan(pixel - *m_panFrom);
            m_panFrom = pixel;
        }
        else if (event.type == sf::Event::MouseButtonReleased && event.mouseButton.button != sf::Mouse::Left)
            m_panFrom.reset();
        return;
    }
    if (event.type == sf::Event::MouseButtonPressed)
        m_ctx.focusScene = true; // the keys belong to the scene again
    if (m_ctx.playing)
    {
        // The play test is drawn in the scene area: its input is in that area's pixels.
        const sf::FloatRect area = m_ctx.sceneArea();
        sf::Event local = event;
        if (event.type == sf::Event::MouseMoved)
        {
            local.mouseMove.x -= static_cast<int>(area.left);
            local.mouseMove.y -= static_cast<int>(area.top);
        }
        else if (event.type == sf::Event::MouseButtonPressed || event.type == sf::Event::MouseButtonReleased)
        {
            local.mouseButton.x -= static_cast<int>(area.left);
            local.mouseButton.y -= static_cast<int>(area.top);
        }
        play.handleSceneEvent(local);
        return;
    }
    if (event.type == sf::Event::MouseButtonPressed && event.mouseButton.button == sf::Mouse::Left)
        pressOnScene(pixel, m_ctx.app.run().input().shift(), m_ctx.app.run().input().ctrl());
    else if (event.type == sf::Event::MouseMoved)
        moveOnScene(pixel);
    else if (event.type == sf::Event::MouseButtonReleased && event.mouseButton.button == sf::Mouse::Left)
        releaseOnScene(pixel);
}

void SceneTools::pressOnScene(sf::Vector2f pixel, bool shift, bool ctrl)
{
    const sf::Vector2f world = m_ctx.view.toWorld(pixel);
    if (tool == Tool::Drop)
    {
        dropHeld(world, shift);
        return;
    }
    if (tool != Tool::Select)
    {
        try
        {
            const ObjectRef placed = m_ctx.scene().place(toolObject(world));
            const auto at = centreOf(objectDef(m_ctx.scene().level(), placed));
            m_ctx.app.trace().write("editor-place", {{"object", pointerOf(placed)}, {"x", at.x}, {"y", at.y}});
            if (!m_ctx.sayIfNotLanded())
                m_ctx.message.clear();
        }
        catch (const std::exception& error)
        {
            m_ctx.message = error.what();
            m_ctx.messageIsError = true;
        }
        // Shift places several; otherwise back to selecting, with the new object selected to adjust.
        if (!shift)
            tool = Tool::Select;
        return;
    }
    if (const auto vertex = vertexHandleAt(pixel))
    {
        pressVertexHandle(*vertex, ctrl);
        return;
    }
    if (const auto handle = resizeHandleAt(pixel))
    {
        m_resizing = handle;
        return;
    }
    const std::optional<ObjectRef> hit = m_ctx.scene().objectAt(world.x, world.y);
    if (!hit)
    {
        // A rectangle selects what it encloses; Shift or Ctrl adds to the selection.
        bandFrom = world;
        m_bandAdds = shift || ctrl;
        return;
    }
    if (shift || ctrl)
    {
        m_ctx.scene().select(*hit, SelectMode::Toggle);
        return;
    }
    m_ctx.scene().beginDrag(*hit);
    m_dragFrom = world;
}

void SceneTools::moveOnScene(sf::Vector2f pixel)
{
    const sf::Vector2f world = m_ctx.view.toWorld(pixel);
    if (m_dragFrom)
        m_ctx.scene().dragTo(world.x - m_dragFrom->x, world.y - m_dragFrom->y);
    else if (m_vertexDrag)
    {
        // On the grid when it is on (a corner is a point: it snaps to the grid itself).
        double x = world.x;
        double y = world.y;
        if (m_ctx.scene().snapSettings().grid)
        {
            const double g = m_ctx.scene().snapSettings().gridM;
            x = std::round(x / g) * g;
            y = std::round(y / g) * g;
        }
        const std::string why =
            m_ctx.scene().moveVertex(m_vertexDrag->terrain, m_vertexDrag->vertex, x, y, "vertex-drag");
        m_ctx.message = why;
        m_ctx.messageIsError = !why.empty();
    }
    else if (m_resizing)
    {
        // The handle follows the pointer in the object's own frame; the bottom edge stays where it is.
        const ObjectDef def = objectDef(m_ctx.scene().level(), *m_resizing);
        double x = 0.0, y = 0.0, h = 0.0, a = 0.0;
        if (const auto* b = std::get_if<BlockDef>(&def))
            std::tie(x, y, h, a) = std::tuple(b->x, b->y, b->heightM, b->angleDeg);
        else if (const auto* t = std::get_if<TerrainDef>(&def))
            std::tie(x, y, h, a) = std::tuple(t->x, t->y, t->heightM, t->angleDeg);
        const double c = std::cos(a * kDegToRad);
        const double s = std::sin(a * kDegToRad);
        const double dx = world.x - x;
        const double dy = world.y - y;
        const double localX = c * dx + s * dy;
        const double localY = -s * dx + c * dy;
        const double step = m_ctx.scene().snapSettings().grid ? m_ctx.scene().snapSettings().gridM : 0.01;
        const auto snapped = [step](double v)
        {
            return std::max(step, std::round(v / step) * step);
        };
        const double width = snapped(2.0 * localX);
        const double height = snapped(localY + h / 2.0);
        const std::string why = m_ctx.scene().resizeObject(*m_resizing, width, height, "resize-handle");
        if (!why.empty())
        {
            m_ctx.message = why;
            m_ctx.messageIsError = true;
        }
    }
}

void SceneTools::releaseOnScene(sf::Vector2f pixel)
{
    const sf::Vector2f world = m_ctx.view.toWorld(pixel);
    if (m_dragFrom)
    {
        m_ctx.scene().endDrag();
        m_dragFrom.reset();
        m_ctx.sayIfNotLanded();
    }
    if (m_resizing || m_vertexDrag)
    {
        m_ctx.scene().endGesture();
        m_resizing.reset();
        m_vertexDrag.reset();
    }
    if (bandFrom)
    {
        const sf::Vector2f from = *bandFrom;
        bandFrom.reset();
        const bool click = std::hypot(world.x - from.x, world.y - from.y) * m_ctx.view.pixelsPerMetre() < 4.0f;
        if (click && !m_bandAdds)
            m_ctx.scene().clearSelection();
        else if (!click)
            m_ctx.scene().selectInRect(from.x, from.y, world.x, world.y,
                                       m_bandAdds ? SelectMode::Add : SelectMode::Replace);
    }
}

Vec2 SceneTools::insertionPoint() const
{
    if (pointerOnScene)
    {
        const sf::Vector2f world = m_ctx.view.toWorld(pointer);
        return {world.x, world.y};
    }
    const sf::FloatRect area = m_ctx.sceneArea();
    const sf::Vector2f centre = m_ctx.view.toWorld({area.left + 0.5f * area.width, area.top + 0.5f * area.height});
    return {centre.x, m_ctx.scene().level().groundY};
}

void SceneTools::chooseHill()
{
    tool = Tool::Terrain;
    terrainTemplate = TerrainDef{};
    terrainTemplate.points = {{-3.0, -0.75}, {3.0, -0.75}, {2.0, 0.25}, {0.5, 0.75}, {-0.5, 0.75}, {-2.0, 0.25}};
    terrainTemplate.widthM = 6.0;
    terrainTemplate.heightM = 1.5;
}

void SceneTools::hold(LevelDef bodies, std::string label)
{
    held = HeldBodies{std::move(bodies), std::move(label)};
    tool = Tool::Drop;
}

void SceneTools::dropHeld(sf::Vector2f world, bool shift)
{
    if (!held)
    {
        tool = Tool::Select;
        return;
    }
    const std::string why = m_ctx.scene().insertBodies(held->bodies, Vec2{world.x, world.y}, held->label);
    const std::size_t count = m_ctx.scene().selection().size();
    m_ctx.message = why.empty() ? held->label + ": " + std::to_string(count) + " bodies dropped"
                                : "Cannot drop " + held->label + ": " + why;
    m_ctx.messageIsError = !why.empty();
    if (why.empty())
        m_ctx.sayIfNotLanded();
    m_ctx.app.trace().write(
        "editor-drop",
        {{"label", held->label}, {"x", world.x}, {"y", world.y}, {"bodies", why.empty() ? count : 0}, {"why", why}});
    // Shift drops another copy; otherwise back to selecting, with the dropped group selected to adjust.
    if (!shift)
    {
        held.reset();
        tool = Tool::Select;
    }
}

void SceneTools::chooseTerrainBox()
{
    tool = Tool::Terrain;
    terrainTemplate = TerrainDef{0.0, 0.0, 4.0, 1.0, 0.0, {}};
}

} // namespace abalike::app
