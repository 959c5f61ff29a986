#pragma once

#include <SFML/System/Vector2.hpp>

namespace abalike::app
{

/// How far the mouse must be able to pull the bird: the full pull's length on the screen and the room the aiming view
/// keeps around the pouch so that a full pull in any launch direction from kLowestDeg to kHighestDeg stays inside
/// the window. The camera keeps the room (CameraRig::homeView) and the aim reads the length (AimController).
namespace pull_reach
{
inline constexpr float kFullPullPxAt720 = 200.0f; ///< a full pull at 720 px of the window's shorter side
inline constexpr float kLowestDeg = -10.0f;       ///< the launch directions a full pull must reach
inline constexpr float kHighestDeg = 80.0f;
inline constexpr float kMarginPx = 24.0f; ///< the pointer at a full pull stays this far inside the window
} // namespace pull_reach

/// A full pull's length in window pixels: 200 px at 720 px of the window's shorter side, scaled with it, so that a
/// tall narrow window does not ask for a pull wider than itself.
float fullPullPx(sf::Vector2u windowSize);

/// The room (window pixels) the pouch needs to its left, below and above it for a full pull in every direction from
/// pull_reach::kLowestDeg to kHighestDeg, with the margin.
struct PullRoom
{
    float left = 0.0f;
    float below = 0.0f;
    float above = 0.0f;
};
PullRoom pullRoomPx(sf::Vector2u windowSize);

} // namespace abalike::app
