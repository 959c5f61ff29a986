#pragma once

#include "render/WorldBox.hpp"

#include <SFML/System/Vector2.hpp>
#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Catalog.hpp>

namespace abalike::app
{

/// Where a camera looks and how close: the world point at the middle of the window and the scale.
struct CameraView
{
    sf::Vector2f centreM;
    float pixelsPerMetre = 1.0f;
};

/// Limits and margins every camera of the game shares.
namespace camera_limits
{
inline constexpr float kMaxPixelsPerMetre = 120.0f; ///< a tiny level should not turn into a close-up
inline constexpr float kMinPixelsPerMetre = 1.0f;   ///< a 1280-pixel window then spans 1.28 km
inline constexpr float kGroundFromBottom = 0.12f;   ///< the ground line sits this far up the window
inline constexpr float kTopReserved = 0.18f;        ///< the top of the window is the HUD's: fitted boxes stay below
} // namespace camera_limits

/// The view a level starts with: from 4 m left of the slingshot to 4 m beyond the furthest block or pig, from the
/// ground to 2 m above the tallest thing (the level as designed, not as it is now).
WorldBox levelHomeBox(const LevelDef& level, const Catalog& catalog);

/// The closest view (within the scale limits) that shows the whole box in a window of this size, uniformly scaled,
/// centred across, with the ground line kept kGroundFromBottom up the window while the box stands on the ground.
/// topReserved: the fraction of the window's top kept clear for panels (the HUD; more with the teaching overlay);
/// groundFromBottom: where the ground line sits, as a fraction of the window up from its bottom.
CameraView fitBox(const WorldBox& box, float groundY, sf::Vector2u windowSize,
                  float topReserved = camera_limits::kTopReserved,
                  float groundFromBottom = camera_limits::kGroundFromBottom);

/// The part of the world a view shows in a window of this size.
WorldBox visibleBox(const CameraView& view, sf::Vector2u windowSize);

} // namespace abalike::app
