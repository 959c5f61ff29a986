#include "render/PullReach.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace abalike::app
{

float fullPullPx(sf::Vector2u windowSize)
{
    const auto shorter = static_cast<float>(std::max(std::min(windowSize.x, windowSize.y), 1u));
    return pull_reach::kFullPullPxAt720 * shorter / 720.0f;
}

PullRoom pullRoomPx(sf::Vector2u windowSize)
{
    // A launch at angle a pulls the pointer to pouch - r (cos a, sin a) in the world (y up): the leftmost reach is at
    // 0°, the lowest at the steepest angle, the highest at the lowest (negative) angle.
    constexpr float kDegToRad = std::numbers::pi_v<float> / 180.0f;
    const float r = fullPullPx(windowSize);
    const float left =
        r * std::max({std::cos(pull_reach::kLowestDeg * kDegToRad), std::cos(pull_reach::kHighestDeg * kDegToRad),
                      pull_reach::kLowestDeg <= 0.0f && pull_reach::kHighestDeg >= 0.0f ? 1.0f : 0.0f});
    const float below = r * std::max(std::sin(pull_reach::kHighestDeg * kDegToRad), 0.0f);
    const float above = r * std::max(-std::sin(pull_reach::kLowestDeg * kDegToRad), 0.0f);
    return {left + pull_reach::kMarginPx, below + pull_reach::kMarginPx, above + pull_reach::kMarginPx};
}

} // namespace abalike::app
