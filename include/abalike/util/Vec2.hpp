#pragma once

#include <compare>

namespace abalike
{

/// A vector in the plane: a position (m), a velocity (m/s), an impulse (N s), a direction; y points up.
struct Vec2
{
    double x = 0.0;
    double y = 0.0;

    bool operator==(const Vec2&) const = default;
    /// By x, then y: an order for sorting points (a convex hull's), not a comparison of lengths.
    auto operator<=>(const Vec2&) const = default;
};

inline Vec2 operator+(const Vec2& a, const Vec2& b)
{
    return {a.x + b.x, a.y + b.y};
}
inline Vec2 operator-(const Vec2& a, const Vec2& b)
{
    return {a.x - b.x, a.y - b.y};
}
inline Vec2 operator-(const Vec2& a)
{
    return {-a.x, -a.y};
}
inline Vec2 operator*(double k, const Vec2& a)
{
    return {k * a.x, k * a.y};
}

/// One coordinate, for code that works along either axis (snapping, distributing): axis 0 is x, any other y.
inline double coordinate(const Vec2& v, int axis)
{
    return axis == 0 ? v.x : v.y;
}

} // namespace abalike
