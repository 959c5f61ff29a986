#include "render/Camera.hpp"

#include <algorithm>
#include <cmath>

namespace abalike::app
{

namespace
{
constexpr double kSideMarginM = 4.0;
constexpr double kTopMarginM = 2.0;
constexpr float kGroundFromBottom = 0.12f;
constexpr float kMaxPixelsPerMetre = 120.0f; // a tiny level should not turn into a close-up

double pigRadius(const PigDef& pig, const Catalog& catalog)
{
    const PigType* type = catalog.findPig(pig.type);
    return type != nullptr ? type->radiusM : 0.5;
}
} // namespace

Camera Camera::fitLevel(const LevelDef& level, const Catalog& catalog, sf::Vector2u windowSize)
{
    const double left = level.slingshot.x - kSideMarginM;
    double furthest = level.slingshot.x + 20.0;
    double top = level.slingshot.y + 1.0;
    bool anyTarget = false;
    for (const BlockDef& block : level.blocks)
    {
        const double halfExtent = 0.5 * std::max(block.widthM, block.heightM);
        furthest = anyTarget ? std::max(furthest, block.x + halfExtent) : block.x + halfExtent;
        anyTarget = true;
        top = std::max(top, block.y + halfExtent);
    }
    for (const PigDef& pig : level.pigs)
    {
        const double radius = pigRadius(pig, catalog);
        furthest = anyTarget ? std::max(furthest, pig.x + radius) : pig.x + radius;
        anyTarget = true;
        top = std::max(top, pig.y + radius);
    }
    for (const TerrainDef& terrain : level.terrain)
        top = std::max(top, terrain.y + 0.5 * terrain.heightM);
    furthest = std::max(furthest, level.slingshot.x + 6.0);
    const double right = furthest + kSideMarginM;

    const auto width = static_cast<float>(std::max(windowSize.x, 1u));
    const auto height = static_cast<float>(std::max(windowSize.y, 1u));
    const float groundScreenY = height * (1.0f - kGroundFromBottom);

    float ppm = width / static_cast<float>(right - left);
    const auto neededAboveGround = static_cast<float>(top - level.groundY + kTopMarginM);
    ppm = std::min({ppm, groundScreenY / neededAboveGround, kMaxPixelsPerMetre});

    // Centre the fitted span when zooming out for height left room at the sides.
    const float spanPixels = static_cast<float>(right - left) * ppm;
    const float worldLeft = static_cast<float>(left) - 0.5f * (width - spanPixels) / ppm;
    const float worldTop = static_cast<float>(level.groundY) + groundScreenY / ppm;
    return Camera({worldLeft, worldTop}, ppm, windowSize);
}

Camera::Camera(sf::Vector2f worldAtScreenOrigin, float pixelsPerMetre, sf::Vector2u windowSize)
    : m_pixelsPerMetre(pixelsPerMetre), m_windowSize(windowSize)
{
    m_transform.scale(pixelsPerMetre, -pixelsPerMetre).translate(-worldAtScreenOrigin);
    m_inverse = m_transform.getInverse();
    const float widthM = static_cast<float>(windowSize.x) / pixelsPerMetre;
    const float heightM = static_cast<float>(windowSize.y) / pixelsPerMetre;
    m_visible = sf::FloatRect(worldAtScreenOrigin.x, worldAtScreenOrigin.y - heightM, widthM, heightM);
}

} // namespace abalike::app
