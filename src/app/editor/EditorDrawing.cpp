#include "editor/EditorScreen.hpp"

#include "render/Palette.hpp"
#include "shell/App.hpp"

#include <SFML/Graphics/RectangleShape.hpp>
#include <cmath>
#include <imgui.h>

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

std::vector<sf::Vector2f> closed(const std::vector<std::array<double, 2>>& outline)
{
    std::vector<sf::Vector2f> points;
    for (const auto& p : outline)
        points.emplace_back(static_cast<float>(p[0]), static_cast<float>(p[1]));
    if (!points.empty())
        points.push_back(points.front());
    return points;
}
} // namespace

void EditorScreen::addOutline(const Camera& camera, const ObjectRef& ref, float widthPx, sf::Color colour)
{
    const std::vector<sf::Vector2f> points = closed(m_editor->outline(ref));
    m_mesh.addPolyline(points, widthPx * camera.metresPerPixel(), colour);
}

void EditorScreen::drawGrid(const Camera& camera, sf::Vector2u size)
{
    if (!m_editor->snapSettings().grid)
        return;
    // The snapping grid where it is at least 16 px apart; every metre stronger.
    double step = m_editor->snapSettings().gridM;
    while (step * camera.pixelsPerMetre() < 16.0)
        step *= 2.0;
    const sf::FloatRect visible = camera.visibleWorld();
    (void)size;
    const float thin = camera.metresPerPixel();
    const double groundY = m_editor->level().groundY;
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

void EditorScreen::drawOverlay(sf::RenderTarget& target)
{
    const Camera camera = m_view.camera(target.getSize());
    const float scale = m_app.uiScale();
    m_mesh.clear();
    drawGrid(camera, target.getSize());

    // Findings in red on their objects (paler once the scene has changed since the check ran).
    for (const Finding& finding : m_checks.findings())
    {
        if (!finding.object || !exists(m_editor->level(), *finding.object))
            continue;
        const auto ran = m_checks.ranOn(finding.source);
        const bool stale = ran && *ran != m_editor->revision();
        addOutline(camera, *finding.object, 4.0f * scale, stale ? kStale : kFinding);
    }
    for (const ObjectRef& ref : m_editor->selection())
        addOutline(camera, ref, 3.0f * scale, kSelected);

    // The resize handle of a single selected block or terrain piece.
    if (m_editor->selection().size() == 1 && m_tool == Tool::Select)
    {
        const ObjectRef ref = m_editor->selection()[0];
        const bool polygon = ref.kind == ObjectKind::Terrain && m_editor->level().terrain[ref.index].isPolygon();
        if (polygon)
        {
            // A polygon's corners (squares: drag to move, Ctrl+click to remove) and its edges' middles (rings:
            // click to add a corner there).
            const float half = 6.0f * scale * camera.metresPerPixel();
            for (const VertexHandle& handle : vertexHandles())
            {
                const sf::Vector2f at = vertexHandlePosition(handle);
                if (handle.edgeMiddle)
                    m_mesh.addRing(at, half, 2.0f * scale * camera.metresPerPixel(), kSelected, 16);
                else
                    m_mesh.addGradientRect(at - sf::Vector2f(half, half), at + sf::Vector2f(half, half), kSelected,
                                           kSelected);
            }
        }
        else if (ref.kind == ObjectKind::Block || ref.kind == ObjectKind::Terrain)
        {
            const auto outline = m_editor->outline(ref);
            const ObjectDef def = objectDef(m_editor->level(), ref);
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
    if (m_tool != Tool::Select && m_pointerOnScene)
    {
        const sf::Vector2f world = m_view.toWorld(m_pointer);
        const ObjectDef object = toolObject(world);
        const SnapResult at = m_editor->snap(object);
        const ObjectDef placed = withCentre(object, at.x, at.y);
        const std::vector<sf::Vector2f> points = closed(m_editor->outlineOf(placed));
        m_mesh.addPolyline(points, 2.0f * scale * camera.metresPerPixel(), kGhost);
    }

    // The selection rectangle being dragged out.
    if (m_bandFrom)
    {
        const sf::Vector2f a = *m_bandFrom;
        const sf::Vector2f b = m_view.toWorld(m_pointer);
        const std::vector<sf::Vector2f> band{{a.x, a.y}, {b.x, a.y}, {b.x, b.y}, {a.x, b.y}, {a.x, a.y}};
        m_mesh.addPolyline(band, 1.5f * scale * camera.metresPerPixel(), kBand);
    }
    m_mesh.draw(target, camera.transform());
}

} // namespace abalike::app
