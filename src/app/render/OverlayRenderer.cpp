#include "render/OverlayRenderer.hpp"

#include "render/LabelPlacement.hpp"
#include "render/ScreenRegions.hpp"

#include "render/Hud.hpp"
#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "render/TextFormat.hpp"

#include <SFML/Graphics/RectangleShape.hpp>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

namespace abalike::app
{

namespace
{
constexpr float kDotRadiusPx = 3.5f;
constexpr float kContactRingPx = 10.0f;

sf::Vector2f toVector(const TrackPoint& point)
{
    return {static_cast<float>(point.position.x), static_cast<float>(point.position.y)};
}

std::vector<sf::Vector2f> worldPoints(std::span<const TrackPoint> path)
{
    std::vector<sf::Vector2f> points;
    points.reserve(path.size());
    for (const auto& point : path)
        points.push_back(toVector(point));
    return points;
}

/// The window grown by margin pixels on every side: what is drawn outside it cannot show (a camera shake moves the
/// picture by a few pixels at most).
sf::FloatRect grownWindow(const Camera& camera, float margin)
{
    const sf::Vector2f size(camera.windowSize());
    return {-margin, -margin, size.x + 2.0f * margin, size.y + 2.0f * margin};
}

/// Adds the parts of a screen polyline that cross the rectangle, each run of visible segments as one polyline: a
/// long flight zoomed in leaves most of its steps off the window.
void addVisiblePolyline(Mesh& mesh, std::span<const sf::Vector2f> points, const sf::FloatRect& window, float width,
                        sf::Color colour)
{
    const auto crosses = [&window](sf::Vector2f a, sf::Vector2f b)
    {
        const sf::FloatRect box(std::min(a.x, b.x), std::min(a.y, b.y), std::abs(a.x - b.x), std::abs(a.y - b.y));
        return window.intersects(box) || window.contains(a);
    };
    std::size_t start = 0;
    for (std::size_t i = 1; i <= points.size(); ++i)
    {
        const bool visible = i < points.size() && crosses(points[i - 1], points[i]);
        if (visible)
            continue;
        if (i - start >= 2)
            mesh.addPolyline(points.subspan(start, i - start), width, colour);
        start = i;
    }
}
} // namespace

void OverlayRenderer::addDots(const Camera& camera, std::span<const sf::Vector2f> points, float radius, float opacity)
{
    std::vector<sf::Vector2f> screen;
    screen.reserve(points.size());
    for (const sf::Vector2f& point : points)
        screen.push_back(camera.toScreen(point));
    // Slow or zoomed-out flights put the steps close together: shrink the dots so they stay dots.
    std::vector<float> gaps;
    for (std::size_t i = 1; i < screen.size(); ++i)
        gaps.push_back(std::hypot(screen[i].x - screen[i - 1].x, screen[i].y - screen[i - 1].y));
    if (!gaps.empty())
    {
        std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
        radius = std::clamp(0.3f * gaps[gaps.size() / 2], 1.5f, radius);
    }
    const float outline = std::min(1.5f, 0.5f * radius);
    // Dots off the window are left out: a zoomed-in view of a long flight shows few of its steps.
    const sf::FloatRect window = grownWindow(camera, radius + outline + 8.0f);
    std::erase_if(screen, [&window](sf::Vector2f point) { return !window.contains(point); });
    for (const sf::Vector2f& point : screen)
        m_mesh.addCircle(point, radius + outline, faded(palette::kPreviewOutline, opacity), 10);
    for (const sf::Vector2f& point : screen)
        m_mesh.addCircle(point, radius, faded(palette::kPreviewDot, opacity), 10);
}

void OverlayRenderer::addPredictedContact(const Camera& camera, const ContactPoint& contact, float opacity)
{
    const sf::Vector2f at = camera.toScreen({static_cast<float>(contact.x), static_cast<float>(contact.y)});
    m_mesh.addRing(at, kContactRingPx, 5.0f, faded(palette::kPreviewOutline, opacity), 28);
    m_mesh.addRing(at, kContactRingPx, 2.5f, faded(palette::kPreviewDot, opacity), 28);
}

void OverlayRenderer::addAbility(const Camera& camera, const AbilityUse& ability, float opacity)
{
    const sf::Color colour = faded(palette::kAbility, opacity);
    const sf::Color dark = faded(palette::kPreviewOutline, opacity);
    const sf::Vector2f at = camera.toScreen({static_cast<float>(ability.x), static_cast<float>(ability.y)});
    constexpr int kRays = 8;
    for (int i = 0; i < kRays; ++i)
    {
        const float angle = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / kRays;
        const sf::Vector2f direction(std::cos(angle), std::sin(angle));
        m_mesh.addLine(at + direction * 6.0f, at + direction * 13.0f, 4.0f, dark);
        m_mesh.addLine(at + direction * 6.0f, at + direction * 13.0f, 2.0f, colour);
    }

    // Impulse arrows share one scale: the largest is 60 px long.
    double largest = 0.0;
    for (const AbilityImpulse& impulse : ability.impulses)
        largest = std::max(largest, std::hypot(impulse.impulseX, impulse.impulseY));
    if (largest <= 0.0)
        return;
    const double pixelsPerNs = 60.0 / largest;
    for (const AbilityImpulse& impulse : ability.impulses)
    {
        const sf::Vector2f from = camera.toScreen({static_cast<float>(impulse.x), static_cast<float>(impulse.y)});
        // Screen y points down, so the impulse's y flips.
        const sf::Vector2f arrow(static_cast<float>(impulse.impulseX * pixelsPerNs),
                                 static_cast<float>(-impulse.impulseY * pixelsPerNs));
        const float length = std::hypot(arrow.x, arrow.y);
        if (length < 4.0f)
            continue;
        const sf::Vector2f unit = arrow / length;
        const sf::Vector2f side(-unit.y, unit.x);
        const sf::Vector2f tip = from + arrow;
        const float head = std::min(8.0f, 0.4f * length);
        m_mesh.addLine(from, tip - unit * head, 4.0f, dark);
        m_mesh.addLine(from, tip - unit * head, 2.0f, colour);
        m_mesh.addTriangle(tip, tip - unit * head + side * (0.6f * head), tip - unit * head - side * (0.6f * head),
                           colour);
    }
}

std::size_t shortPreviewDots(const PredictedFlight& preview)
{
    constexpr std::size_t kLeastDots = 30; // half a second of 1/60 s steps
    std::size_t dots = 0;
    while (dots < preview.path.size() && preview.path[dots].state.velocity.y > 0.0)
        ++dots;
    return std::min(std::max(dots, kLeastDots), preview.path.size());
}

void OverlayRenderer::drawPreview(sf::RenderTarget& target, const Camera& camera, const PredictedFlight& preview,
                                  std::size_t maxDots)
{
    m_mesh.clear();
    const std::size_t count = maxDots == 0 ? preview.path.size() : std::min(maxDots, preview.path.size());
    std::vector<sf::Vector2f> points;
    points.reserve(count);
    for (std::size_t i = 0; i < count; ++i)
        points.emplace_back(static_cast<float>(preview.path[i].state.position.x),
                            static_cast<float>(preview.path[i].state.position.y));
    addDots(camera, points, kDotRadiusPx, 1.0f);
    if (preview.contact && count == preview.path.size())
        addPredictedContact(camera, *preview.contact, 1.0f);
    m_mesh.draw(target);
}

void OverlayRenderer::drawShotPaths(sf::RenderTarget& target, const Camera& camera, const ShotRecord& shot,
                                    float opacity)
{
    m_mesh.clear();
    // The flown path underneath, the prediction's dots on top: where they agree, the dots sit on the line.
    std::vector<sf::Vector2f> actual = worldPoints(shot.actualPath);
    for (sf::Vector2f& point : actual)
        point = camera.toScreen(point);
    const sf::FloatRect window = grownWindow(camera, 16.0f);
    addVisiblePolyline(m_mesh, actual, window, 6.0f, faded(sf::Color(90, 40, 0), 0.5f * opacity));
    addVisiblePolyline(m_mesh, actual, window, 4.0f, faded(palette::kActualPath, opacity));
    addDots(camera, worldPoints(shot.predictedPath), kDotRadiusPx - 1.5f, 0.6f * opacity);
    m_mesh.draw(target);
}

void OverlayRenderer::drawShotMarkers(sf::RenderTarget& target, const Camera& camera, const ShotRecord& shot,
                                      float opacity)
{
    m_mesh.clear();
    if (shot.ability)
        addAbility(camera, *shot.ability, opacity);
    if (shot.predictedContact)
        addPredictedContact(camera, *shot.predictedContact, opacity);
    if (shot.actualContact)
    {
        const sf::Vector2f actualAt =
            camera.toScreen({static_cast<float>(shot.actualContact->x), static_cast<float>(shot.actualContact->y)});
        constexpr float kArm = 6.0f;
        for (const float width : {5.0f, 3.0f})
        {
            const sf::Color colour = width > 4.0f ? sf::Color(255, 255, 255) : palette::kActualContact;
            m_mesh.addLine(actualAt + sf::Vector2f(-kArm, -kArm), actualAt + sf::Vector2f(kArm, kArm), width,
                           faded(colour, opacity));
            m_mesh.addLine(actualAt + sf::Vector2f(-kArm, kArm), actualAt + sf::Vector2f(kArm, -kArm), width,
                           faded(colour, opacity));
        }
    }
    m_mesh.draw(target);
}

void OverlayRenderer::drawShotLabel(sf::RenderTarget& target, const Camera& camera, const ShotRecord& shot,
                                    float opacity, std::span<const sf::FloatRect> structure,
                                    std::span<const sf::FloatRect> keep, float textScale, bool chip)
{
    if (m_font == nullptr || !shot.actualContact || !(shot.deviationM || shot.launchedIntoMovingWorld))
        return;
    if (chip && !shot.deviationM)
        return; // no deviation to show
    const sf::Vector2f actualAt =
        camera.toScreen({static_cast<float>(shot.actualContact->x), static_cast<float>(shot.actualContact->y)});
    // Next to the contact, in free sky: off the structure if there is room, inside the window.
    const float scale = hudScale(camera.windowSize());
    const auto size = static_cast<unsigned>(std::max(9.0f, std::round((chip ? 13.0f : 16.0f) * scale * textScale)));
    // Into a moving world the preview aimed at where the blocks were at launch: no deviation is claimed.
    const sf::String text = utf8(chip              ? formatDistance(*shot.deviationM)
                                 : shot.deviationM ? "predicted vs actual: " + formatDistance(*shot.deviationM)
                                                   : std::string("launched while blocks moved: no deviation scored"));
    const sf::Vector2f extent = measureText(*m_font, text, size);
    const float pad = 0.4f * static_cast<float>(size);
    // Clear of every panel drawn this frame and of what must stay in view and, where there is room, of the rest of
    // the structure; with no spot clear of both inside the window it is left out rather than drawn over them.
    const sf::Vector2f boxSize = extent + sf::Vector2f(2.0f * pad, 2.0f * pad);
    const sf::Vector2f window(camera.windowSize());
    const std::vector<sf::FloatRect> panels = rectsOf(screenLayout());
    std::vector<sf::FloatRect> avoid(structure.begin(), structure.end());
    avoid.insert(avoid.end(), panels.begin(), panels.end());
    std::vector<sf::FloatRect> panelsAndKeep = panels;
    panelsAndKeep.insert(panelsAndKeep.end(), keep.begin(), keep.end());
    const auto clear = [&](sf::Vector2f corner)
    {
        return corner.x >= 0.0f && corner.y >= 0.0f && corner.x + boxSize.x <= window.x &&
               corner.y + boxSize.y <= window.y && coveredArea({corner, boxSize}, panelsAndKeep) <= 0.0f;
    };
    sf::Vector2f at = placeLabel(actualAt, boxSize, window, avoid, 18.0f * scale);
    if (!clear(at))
        at = placeLabel(actualAt, boxSize, window, panelsAndKeep, 18.0f * scale);
    if (!clear(at))
        return;

    sf::RectangleShape box({extent.x + 2.0f * pad, extent.y + 2.0f * pad});
    box.setPosition(at);
    recordScreenRegion("predicted vs actual", {at, box.getSize()});
    box.setFillColor(faded(palette::kPanel, opacity));
    box.setOutlineColor(faded(palette::kActualPath, opacity));
    box.setOutlineThickness(1.5f);
    target.draw(box);
    const TextKindScope kind(chip ? TextKind::Hud : TextKind::Physics);
    drawLabel(target, *m_font, text, at + sf::Vector2f(pad, pad), size, faded(palette::kText, opacity));
}

} // namespace abalike::app
