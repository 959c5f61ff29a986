#include "editor/SceneDrawing.hpp"

#include "editor/EditorContext.hpp"
#include "editor/SceneTools.hpp"
#include "render/Palette.hpp"
#include "shell/AppContext.hpp"
#include "shell/UiMetrics.hpp"

#include <SFML/Graphics/RectangleShape.hpp>
#include <algorithm>
#include <cmath>
#include <imgui.h>
#include <limits>

namespace abalike::app
{

namespace
{
const sf::Color kGridMinor(255, 255, 255, 28);
const sf::Color kGridMajor(255, 255, 255, 70);
const sf::Color kSelected(255, 214, 40);
const sf::Color kFinding(235, 40, 40);
const sf::Color kStale(235, 130, 130);
const sf::Color kGhost(255, 255, 255, 150);
const sf::Color kBand(120, 190, 255);

std::vector<sf::Vector2f> closed(const std::vector<Vec2>& outline)
{
    std::vector<sf::Vector2f> points;
    for (const auto& p : outline)
        points.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
    if (!points.empty())
        points.push_back(points.front());
    return points;
}
} // namespace

void SceneDrawing::addOutline(const Camera& camera, const ObjectRef& ref, float widthPx, sf::Color colour)
{
    const std::vector<sf::Vector2f> points = closed(m_ctx.scene().outline(ref));
    m_mesh.addPolyline(points, widthPx * camera.metresPerPixel(), colour);
}

void SceneDrawing::addHeldOutline(const Camera& camera, sf::Vector2f pointer, float widthPx)
{
    // Exactly where a click would drop them: the same placement (grid, settling onto what is below) as the drop.
    const Vec2 at{pointer.x, pointer.y};
    for (const ObjectDef& def : m_ctx.scene().placedBodies(m_tools.held->bodies, at))
        m_mesh.addPolyline(closed(m_ctx.scene().outlineOf(def)), widthPx * camera.metresPerPixel(), kGhost);
}

void SceneDrawing::drawGrid(const Camera& camera)
{
    if (!m_ctx.scene().snapSettings().grid)
        return;
    // The snapping grid where it is at least 16 px apart; every metre stronger.
    double step = m_ctx.scene().snapSettings().gridM;
    while (step * camera.pixelsPerMetre() < 16.0)
        step *= 2.0;
    const sf::FloatRect visible = camera.visibleWorld();
    const float thin = camera.metresPerPixel();
    const double groundY = m_ctx.scene().level().groundY;
    const double x0 = std::floor(visible.left / step) * step;
    for (double x = x0; x <= visible.left + visible.width; x += step)
    {
        const bool major = std::abs(x - std::round(x)) < 1e-6;
        m_mesh.addLine({static_cast<float>(x), static_cast<float>(groundY)},
                       {static_cast<float>(x), visible.top + visible.height}, thin, major ? kGridMajor : kGridMinor);
    }
    const double y0 = std::max(groundY, std::floor(visible.top / step) * step);
    for (double y = y0; y <= visible.top + visible.height; y += step)
    {
        const bool major = std::abs(y - std::round(y)) < 1e-6;
        m_mesh.addLine({visible.left, static_cast<float>(y)}, {visible.left + visible.width, static_cast<float>(y)},
                       thin, major ? kGridMajor : kGridMinor);
    }
}

void SceneDrawing::drawOverlay(sf::RenderTarget& target)
{
    const Camera camera = m_ctx.view.camera(target.getSize());
    const float scale = m_ctx.app.ui().scale();
    m_mesh.clear();
    drawGrid(camera);

    // Findings in red on their objects (paler once the scene has changed since the check ran).
    for (const Finding& finding : m_ctx.checks.findings())
    {
        if (!finding.object || !exists(m_ctx.scene().level(), *finding.object))
            continue;
        const auto ran = m_ctx.checks.ranOn(finding.source);
        const bool stale = ran && *ran != m_ctx.scene().revision();
        addOutline(camera, *finding.object, 4.0f * scale, stale ? kStale : kFinding);
    }
    for (const ObjectRef& ref : m_ctx.scene().selection())
        addOutline(camera, ref, 3.0f * scale, kSelected);

    // The resize handle of a single selected block or terrain piece.
    if (m_ctx.scene().selection().size() == 1 && m_tools.tool == SceneTools::Tool::Select)
    {
        const ObjectRef ref = m_ctx.scene().selection()[0];
        const bool polygon = ref.kind == ObjectKind::Terrain && m_ctx.scene().level().terrain[ref.index].isPolygon();
        if (polygon)
        {
            // A polygon's corners (squares: drag to move, Ctrl+click to remove) and its edges' middles (rings:
            // click to add a corner there).
            const float half = 6.0f * scale * camera.metresPerPixel();
            for (const SceneTools::VertexHandle& handle : m_tools.vertexHandles())
            {
                const sf::Vector2f at = m_tools.vertexHandlePosition(handle);
                if (handle.edgeMiddle)
                    m_mesh.addRing(at, half, 2.0f * scale * camera.metresPerPixel(), kSelected, 16);
                else
                    m_mesh.addGradientRect(at - sf::Vector2f(half, half), at + sf::Vector2f(half, half), kSelected,
                                           kSelected);
            }
        }
        else if (ref.kind == ObjectKind::Block || ref.kind == ObjectKind::Terrain)
        {
            const auto outline = m_ctx.scene().outline(ref);
            const ObjectDef def = objectDef(m_ctx.scene().level(), ref);
            // The top-right corner in the object's frame: the outline's third vertex for boxes and frames.
            double a = 0.0;
            double cx = 0.0, cy = 0.0, w = 0.0, h = 0.0;
            if (const auto* b = std::get_if<BlockDef>(&def))
                std::tie(cx, cy, w, h, a) = std::tuple(b->x, b->y, b->widthM, b->heightM, b->angleDeg);
            else if (const auto* t = std::get_if<TerrainDef>(&def))
                std::tie(cx, cy, w, h, a) = std::tuple(t->x, t->y, t->widthM, t->heightM, t->angleDeg);
            const double r = a * 3.14159265358979323846 / 180.0;
            const sf::Vector2f corner(static_cast<float>(cx + std::cos(r) * w / 2 - std::sin(r) * h / 2),
                                      static_cast<float>(cy + std::sin(r) * w / 2 + std::cos(r) * h / 2));
            const float half = 6.0f * scale * camera.metresPerPixel();
            m_mesh.addGradientRect(corner - sf::Vector2f(half, half), corner + sf::Vector2f(half, half), kSelected,
                                   kSelected);
        }
    }

    // Where the current tool would put its object, snapped as it will be.
    if (m_tools.tool == SceneTools::Tool::Drop && m_tools.held && m_tools.pointerOnScene)
        addHeldOutline(camera, m_ctx.view.toWorld(m_tools.pointer), 2.0f * scale);
    else if (m_tools.tool != SceneTools::Tool::Select && m_tools.pointerOnScene)
    {
        const sf::Vector2f world = m_ctx.view.toWorld(m_tools.pointer);
        const ObjectDef object = m_tools.toolObject(world);
        const SnapResult at = m_ctx.scene().snap(object);
        const ObjectDef placed = withCentre(object, at.x, at.y);
        const std::vector<sf::Vector2f> points = closed(m_ctx.scene().outlineOf(placed));
        m_mesh.addPolyline(points, 2.0f * scale * camera.metresPerPixel(), kGhost);
    }

    // The selection rectangle being dragged out.
    if (m_tools.bandFrom)
    {
        const sf::Vector2f a = *m_tools.bandFrom;
        const sf::Vector2f b = m_ctx.view.toWorld(m_tools.pointer);
        const std::vector<sf::Vector2f> band{{a.x, a.y}, {b.x, a.y}, {b.x, b.y}, {a.x, b.y}, {a.x, a.y}};
        m_mesh.addPolyline(band, 1.5f * scale * camera.metresPerPixel(), kBand);
    }
    m_mesh.draw(target, camera.transform());
}

void SceneDrawing::refresh()
{
    const SceneEditor& scene = m_ctx.scene();
    if (m_session && m_generation == m_ctx.sceneGeneration && m_revision == scene.revision())
        return;
    m_generation = m_ctx.sceneGeneration;
    m_revision = scene.revision();
    try
    {
        m_session = std::make_unique<GameSession>(scene.level(), Catalog::builtin());
        m_error.clear();
    }
    catch (const std::exception& error)
    {
        m_error = error.what(); // the model keeps the level loadable; say so if it ever is not
    }
}

void SceneDrawing::draw(sf::RenderTarget& target)
{
    if (!m_session)
        return;
    const Camera camera = m_ctx.view.camera(target.getSize());
    m_renderer.drawBackground(target, camera, *m_session);
    m_renderer.drawForeground(target, camera, *m_session, {0.0f, 0.0f});
    drawOverlay(target);
}

} // namespace abalike::app
