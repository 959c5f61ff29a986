#include "render/ConvexPolygon.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace abalike::app::convex
{

namespace
{
float cross(sf::Vector2f a, sf::Vector2f b)
{
    return a.x * b.y - a.y * b.x;
}

float dot(sf::Vector2f a, sf::Vector2f b)
{
    return a.x * b.x + a.y * b.y;
}

sf::Vector2f leftNormal(sf::Vector2f edge)
{
    const float length = std::sqrt(dot(edge, edge));
    return length > 0.0f ? sf::Vector2f(-edge.y / length, edge.x / length) : sf::Vector2f();
}
} // namespace

std::vector<sf::Vector2f> inset(std::span<const sf::Vector2f> polygon, float distance)
{
    // The polygon cut by every edge moved inwards by `distance` (Sutherland-Hodgman with half-planes). Unlike
    // moving each vertex along its bisector, this stays right when edges are shorter than the distance (a block's
    // chamfered corners): those edges simply vanish.
    const std::size_t n = polygon.size();
    if (n < 3 || signedArea(polygon) <= 0.0f)
        return {};
    std::vector<sf::Vector2f> result(polygon.begin(), polygon.end());
    for (std::size_t i = 0; i < n && result.size() >= 3; ++i)
    {
        const sf::Vector2f edge = polygon[(i + 1) % n] - polygon[i];
        const sf::Vector2f inward = leftNormal(edge);
        if (inward == sf::Vector2f())
            continue;
        const auto inside = [&](sf::Vector2f p)
        {
            return dot(p - polygon[i], inward) - distance;
        };
        std::vector<sf::Vector2f> kept;
        kept.reserve(result.size() + 1);
        for (std::size_t k = 0; k < result.size(); ++k)
        {
            const sf::Vector2f p = result[k];
            const sf::Vector2f q = result[(k + 1) % result.size()];
            const float dp = inside(p);
            const float dq = inside(q);
            if (dp >= 0.0f)
                kept.push_back(p);
            if ((dp >= 0.0f) != (dq >= 0.0f))
                kept.push_back(p + (q - p) * (dp / (dp - dq)));
        }
        result = std::move(kept);
    }
    if (result.size() < 3 || signedArea(result) <= 0.0f)
        return {};
    return result;
}

bool clipSegment(std::span<const sf::Vector2f> polygon, sf::Vector2f& a, sf::Vector2f& b)
{
    // Cyrus-Beck: keep the part of a + t (b - a) on the inner side of every edge.
    const sf::Vector2f d = b - a;
    float tEnter = 0.0f;
    float tLeave = 1.0f;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        const sf::Vector2f edge = polygon[(i + 1) % n] - polygon[i];
        const sf::Vector2f inward = leftNormal(edge);
        const float distanceInside = dot(a - polygon[i], inward);
        const float rate = dot(d, inward);
        if (std::abs(rate) < 1e-12f)
        {
            if (distanceInside < 0.0f)
                return false;
            continue;
        }
        const float t = -distanceInside / rate;
        if (rate > 0.0f)
            tEnter = std::max(tEnter, t);
        else
            tLeave = std::min(tLeave, t);
        if (tEnter > tLeave)
            return false;
    }
    const sf::Vector2f start = a + d * tEnter;
    b = a + d * tLeave;
    a = start;
    return true;
}

bool contains(std::span<const sf::Vector2f> polygon, sf::Vector2f point)
{
    for (std::size_t i = 0; i < polygon.size(); ++i)
    {
        if (cross(polygon[(i + 1) % polygon.size()] - polygon[i], point - polygon[i]) < 0.0f)
            return false;
    }
    return true;
}

sf::FloatRect bounds(std::span<const sf::Vector2f> polygon)
{
    if (polygon.empty())
        return {};
    sf::Vector2f lo = polygon[0];
    sf::Vector2f hi = polygon[0];
    for (const sf::Vector2f& p : polygon)
    {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    return {lo, hi - lo};
}

float signedArea(std::span<const sf::Vector2f> polygon)
{
    float twiceArea = 0.0f;
    for (std::size_t i = 0; i < polygon.size(); ++i)
        twiceArea += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
    return 0.5f * twiceArea;
}

std::vector<sf::Vector2f> circle(sf::Vector2f centre, float radius, int segments)
{
    std::vector<sf::Vector2f> points;
    points.reserve(static_cast<std::size_t>(segments));
    for (int i = 0; i < segments; ++i)
    {
        const float angle = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / static_cast<float>(segments);
        points.emplace_back(centre.x + radius * std::cos(angle), centre.y + radius * std::sin(angle));
    }
    return points;
}

} // namespace abalike::app::convex
