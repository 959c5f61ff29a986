#include "editor/EditorView.hpp"

#include <algorithm>

namespace abalike::app
{

namespace
{
constexpr float kMinPixelsPerMetre = 2.0f;
constexpr float kMaxPixelsPerMetre = 400.0f;
constexpr float kMarginM = 1.5f;
} // namespace

void EditorView::fit(const LevelDef& level, const Catalog& catalog, sf::FloatRect area, sf::Vector2u windowSize)
{
    (void)windowSize;
    float left = static_cast<float>(level.slingshot.x) - 2.0f * kMarginM; // the waiting birds sit behind it
    float right = static_cast<float>(level.slingshot.x) + 20.0f;          // room to build in an empty scene
    const auto ground = static_cast<float>(level.groundY);
    float top = static_cast<float>(level.slingshot.y) + 4.0f;
    const auto include = [&](double x, double y, double halfW, double halfH)
    {
        left = std::min(left, static_cast<float>(x - halfW) - kMarginM);
        right = std::max(right, static_cast<float>(x + halfW) + kMarginM);
        top = std::max(top, static_cast<float>(y + halfH) + 2.0f);
    };
    for (const BlockDef& b : level.blocks)
        include(b.x, b.y, 0.5 * std::max(b.widthM, b.heightM), 0.5 * std::max(b.widthM, b.heightM));
    for (const PigDef& p : level.pigs)
        if (const PigType* type = catalog.findPig(p.type))
            include(p.x, p.y, type->radiusM, type->radiusM);
    for (const TerrainDef& t : level.terrain)
        include(t.x, t.y, 0.5 * std::max(t.widthM, t.heightM), 0.5 * std::max(t.widthM, t.heightM));
    // The ground line a strip of earth above the area's bottom edge, the rest of the height for what stands on it.
    const float earthPx = std::min(60.0f, 0.12f * area.height);
    const float width = std::max(area.width, 50.0f);
    const float height = std::max(area.height - earthPx, 50.0f);
    m_pixelsPerMetre =
        std::clamp(std::min(width / (right - left), height / (top - ground)), kMinPixelsPerMetre, kMaxPixelsPerMetre);
    const float centreX = 0.5f * (left + right);
    m_origin.x = centreX - (area.left + 0.5f * width) / m_pixelsPerMetre;
    m_origin.y = ground + (area.top + area.height - earthPx) / m_pixelsPerMetre;
}

void EditorView::pan(sf::Vector2f pixels)
{
    m_origin.x -= pixels.x / m_pixelsPerMetre;
    m_origin.y += pixels.y / m_pixelsPerMetre;
}

void EditorView::zoomAt(sf::Vector2f pixel, float factor)
{
    const sf::Vector2f anchor = toWorld(pixel);
    m_pixelsPerMetre = std::clamp(m_pixelsPerMetre * factor, kMinPixelsPerMetre, kMaxPixelsPerMetre);
    m_origin.x = anchor.x - pixel.x / m_pixelsPerMetre;
    m_origin.y = anchor.y + pixel.y / m_pixelsPerMetre;
}

Camera EditorView::camera(sf::Vector2u windowSize) const
{
    return Camera::fromView(m_origin, m_pixelsPerMetre, windowSize);
}

sf::Vector2f EditorView::toWorld(sf::Vector2f pixel) const
{
    return {m_origin.x + pixel.x / m_pixelsPerMetre, m_origin.y - pixel.y / m_pixelsPerMetre};
}

} // namespace abalike::app
