#include "render/OverlayRenderer.hpp"

#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "render/TextFormat.hpp"

#include <SFML/Graphics/RectangleShape.hpp>

#include <algorithm>
#include <vector>

namespace abalike::app
{

namespace
{
constexpr float kDotRadiusPx = 3.5f;
constexpr float kContactRingPx = 10.0f;

sf::Vector2f toVector(const std::array<double, 3>& point)
{
    return {static_cast<float>(point[1]), static_cast<float>(point[2])};
}

std::vector<sf::Vector2f> worldPoints(std::span<const std::array<double, 3>> path)
{
    std::vector<sf::Vector2f> points;
    points.reserve(path.size());
    for (const auto& point : path)
        points.push_back(toVector(point));
    return points;
}
} // namespace

void OverlayRenderer::addDots(const Camera& camera, std::span<const sf::Vector2f> points, float radius,
                              float opacity)
{
    for (const sf::Vector2f& point : points)
        m_mesh.addCircle(camera.toScreen(point), radius + 1.5f, faded(palette::kPreviewOutline, opacity), 10);
    for (const sf::Vector2f& point : points)
        m_mesh.addCircle(camera.toScreen(point), radius, faded(palette::kPreviewDot, opacity), 10);
}

void OverlayRenderer::addPredictedContact(const Camera& camera, const ContactPoint& contact, float opacity)
{
    const sf::Vector2f at = camera.toScreen({static_cast<float>(contact.x), static_cast<float>(contact.y)});
    m_mesh.addRing(at, kContactRingPx, 5.0f, faded(palette::kPreviewOutline, opacity), 28);
    m_mesh.addRing(at, kContactRingPx, 2.5f, faded(palette::kPreviewDot, opacity), 28);
}

void OverlayRenderer::drawPreview(sf::RenderTarget& target, const Camera& camera, const PredictedFlight& preview)
{
    m_mesh.clear();
    std::vector<sf::Vector2f> points;
    points.reserve(preview.path.size());
    for (const PathPoint& point : preview.path)
        points.emplace_back(static_cast<float>(point.s[0]), static_cast<float>(point.s[1]));
    addDots(camera, points, kDotRadiusPx, 1.0f);
    if (preview.contact)
        addPredictedContact(camera, *preview.contact, 1.0f);
    m_mesh.draw(target);
}

void OverlayRenderer::drawShot(sf::RenderTarget& target, const Camera& camera, const ShotOverlay& shot, float opacity)
{
    m_mesh.clear();
    addDots(camera, worldPoints(shot.predictedPath), kDotRadiusPx - 1.0f, 0.55f * opacity);

    std::vector<sf::Vector2f> actual = worldPoints(shot.actualPath);
    for (sf::Vector2f& point : actual)
        point = camera.toScreen(point);
    m_mesh.addPolyline(actual, 5.5f, faded(sf::Color(90, 40, 0), 0.6f * opacity));
    m_mesh.addPolyline(actual, 3.0f, faded(palette::kActualPath, opacity));

    if (shot.predictedContact)
        addPredictedContact(camera, *shot.predictedContact, opacity);
    std::optional<sf::Vector2f> actualAt;
    if (shot.actualContact)
    {
        actualAt = camera.toScreen({static_cast<float>(shot.actualContact->x), static_cast<float>(shot.actualContact->y)});
        constexpr float kArm = 6.0f;
        for (const float width : {5.0f, 3.0f})
        {
            const sf::Color colour = width > 4.0f ? sf::Color(255, 255, 255) : palette::kActualContact;
            m_mesh.addLine(*actualAt + sf::Vector2f(-kArm, -kArm), *actualAt + sf::Vector2f(kArm, kArm), width,
                           faded(colour, opacity));
            m_mesh.addLine(*actualAt + sf::Vector2f(-kArm, kArm), *actualAt + sf::Vector2f(kArm, -kArm), width,
                           faded(colour, opacity));
        }
    }
    m_mesh.draw(target);

    if (m_font == nullptr || !shot.deviationM || !actualAt)
        return;
    // The label sits above and left of the contact, kept inside the window.
    const unsigned size = std::max(12u, camera.windowSize().y / 48u);
    const sf::String text = utf8("predicted vs actual: " + formatDistance(*shot.deviationM));
    const sf::Vector2f extent = measureText(*m_font, text, size);
    const float pad = 0.4f * static_cast<float>(size);
    sf::Vector2f at = *actualAt + sf::Vector2f(-extent.x - 2.0f * pad - 14.0f, -extent.y - 2.0f * pad - 20.0f);
    const sf::Vector2f window(camera.windowSize());
    at.x = std::clamp(at.x, 4.0f, std::max(4.0f, window.x - extent.x - 2.0f * pad - 4.0f));
    at.y = std::clamp(at.y, 4.0f, std::max(4.0f, window.y - extent.y - 2.0f * pad - 4.0f));

    sf::RectangleShape box({extent.x + 2.0f * pad, extent.y + 2.0f * pad});
    box.setPosition(at);
    box.setFillColor(faded(palette::kPanel, opacity));
    box.setOutlineColor(faded(palette::kActualPath, opacity));
    box.setOutlineThickness(1.5f);
    target.draw(box);
    drawLabel(target, *m_font, text, at + sf::Vector2f(pad, pad), size, faded(palette::kText, opacity));
}

} // namespace abalike::app
