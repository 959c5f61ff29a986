#include "render/CameraFit.hpp"

#include <algorithm>
#include <cmath>

namespace abalike::app
{

namespace
{
constexpr float kSideMarginM = 4.0f;
constexpr float kTopMarginM = 2.0f;

float pigRadius(const PigDef& pig, const Catalog& catalog)
{
    const PigType* type = catalog.findPig(pig.type);
    return type != nullptr ? static_cast<float>(type->radiusM) : 0.5f;
}

sf::Vector2f windowPixels(sf::Vector2u windowSize)
{
    return {static_cast<float>(std::max(windowSize.x, 1u)), static_cast<float>(std::max(windowSize.y, 1u))};
}
} // namespace

WorldBox levelHomeBox(const LevelDef& level, const Catalog& catalog)
{
    const auto slingX = static_cast<float>(level.slingshot.x);
    float furthest = slingX + 20.0f;
    float top = static_cast<float>(level.slingshot.y) + 1.0f;
    bool anyTarget = false;
    const auto reach = [&](float right)
    {
        furthest = anyTarget ? std::max(furthest, right) : right;
        anyTarget = true;
    };
    for (const BlockDef& block : level.blocks)
    {
        const auto halfExtent = static_cast<float>(0.5 * std::max(block.widthM, block.heightM));
        reach(static_cast<float>(block.x) + halfExtent);
        top = std::max(top, static_cast<float>(block.y) + halfExtent);
    }
    for (const PigDef& pig : level.pigs)
    {
        const float radius = pigRadius(pig, catalog);
        reach(static_cast<float>(pig.x) + radius);
        top = std::max(top, static_cast<float>(pig.y) + radius);
    }
    for (const TerrainDef& terrain : level.terrain)
        top = std::max(top, static_cast<float>(terrain.y + 0.5 * terrain.heightM));
    furthest = std::max(furthest, slingX + 6.0f);
    return {slingX - kSideMarginM, static_cast<float>(level.groundY), furthest + kSideMarginM, top + kTopMarginM};
}

CameraView fitBox(const WorldBox& box, float groundY, sf::Vector2u windowSize, float topReserved,
                  float groundFromBottom)
{
    using namespace camera_limits;
    const sf::Vector2f window = windowPixels(windowSize);
    // While the box stands on the ground, the ground keeps its place near the bottom edge so the horizon does not
    // bob as the camera follows; a box reaching below the ground gets the same margin under its own bottom.
    const float base = std::min(box.bottom, groundY);
    const float heightNeeded = std::max(box.top - base, 0.01f) / (1.0f - groundFromBottom - topReserved);
    const float widthNeeded = std::max(box.width(), 0.01f);
    const float ppm =
        std::clamp(std::min(window.x / widthNeeded, window.y / heightNeeded), kMinPixelsPerMetre, kMaxPixelsPerMetre);
    const float visibleHeight = window.y / ppm;
    const float bottom = base - groundFromBottom * visibleHeight;
    return {{box.centre().x, bottom + 0.5f * visibleHeight}, ppm};
}

WorldBox visibleBox(const CameraView& view, sf::Vector2u windowSize)
{
    const sf::Vector2f window = windowPixels(windowSize);
    const float halfWidth = 0.5f * window.x / view.pixelsPerMetre;
    const float halfHeight = 0.5f * window.y / view.pixelsPerMetre;
    return {view.centreM.x - halfWidth, view.centreM.y - halfHeight, view.centreM.x + halfWidth,
            view.centreM.y + halfHeight};
}

} // namespace abalike::app
