#pragma once

#include <SFML/System/Vector2.hpp>
#include <algorithm>

namespace abalike::app
{

/// An axis-aligned box in world metres, y up: what the camera is asked to keep in view.
struct WorldBox
{
    float left = 0.0f;
    float bottom = 0.0f;
    float right = 0.0f;
    float top = 0.0f;

    /// The square of half-size `radius` around a point.
    static WorldBox around(sf::Vector2f point, float radius)
    {
        return {point.x - radius, point.y - radius, point.x + radius, point.y + radius};
    }

    float width() const { return right - left; }
    float height() const { return top - bottom; }
    sf::Vector2f centre() const { return {0.5f * (left + right), 0.5f * (bottom + top)}; }

    bool contains(sf::Vector2f point) const
    {
        return point.x >= left && point.x <= right && point.y >= bottom && point.y <= top;
    }
    bool contains(const WorldBox& other) const
    {
        return other.left >= left && other.right <= right && other.bottom >= bottom && other.top <= top;
    }
    bool intersects(const WorldBox& other) const
    {
        return other.left < right && other.right > left && other.bottom < top && other.top > bottom;
    }
    WorldBox united(const WorldBox& other) const
    {
        return {std::min(left, other.left), std::min(bottom, other.bottom), std::max(right, other.right),
                std::max(top, other.top)};
    }
    WorldBox expanded(float marginM) const
    {
        return {left - marginM, bottom - marginM, right + marginM, top + marginM};
    }
};

} // namespace abalike::app
