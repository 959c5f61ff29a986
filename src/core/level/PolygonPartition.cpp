#include <abalike/level/PolygonPartition.hpp>
#include <algorithm>
#include <cmath>

namespace abalike
{

namespace
{

double cross(const Vec2& o, const Vec2& a, const Vec2& b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

bool onSegment(const Vec2& p, const Vec2& a, const Vec2& b)
{
    return std::min(a.x, b.x) - 1e-12 <= p.x && p.x <= std::max(a.x, b.x) + 1e-12 &&
           std::min(a.y, b.y) - 1e-12 <= p.y && p.y <= std::max(a.y, b.y) + 1e-12;
}

/// Whether segments ab and cd share any point.
bool segmentsMeet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d)
{
    const double d1 = cross(c, d, a);
    const double d2 = cross(c, d, b);
    const double d3 = cross(a, b, c);
    const double d4 = cross(a, b, d);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return true;
    return (d1 == 0 && onSegment(a, c, d)) || (d2 == 0 && onSegment(b, c, d)) || (d3 == 0 && onSegment(c, a, b)) ||
           (d4 == 0 && onSegment(d, a, b));
}

bool insideTriangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c)
{
    // Counter-clockwise triangle; points on its edges count as inside (they would make the ear overlap).
    return cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0;
}

bool convex(const std::vector<Vec2>& polygon)
{
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i)
        if (cross(polygon[i], polygon[(i + 1) % n], polygon[(i + 2) % n]) < -1e-12)
            return false;
    return true;
}

/// The union of two counter-clockwise polygons that share the edge a[i] -> a[i+1] (b runs it the other way), or
/// empty when they do not share an edge.
std::vector<Vec2> mergeAlongSharedEdge(const std::vector<Vec2>& a, const std::vector<Vec2>& b)
{
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        const Vec2& p = a[i];
        const Vec2& q = a[(i + 1) % a.size()];
        for (std::size_t j = 0; j < b.size(); ++j)
        {
            if (b[j] != q || b[(j + 1) % b.size()] != p)
                continue;
            // a from q round to p, then b from p round to q (without repeating p and q).
            std::vector<Vec2> merged;
            for (std::size_t k = 0; k < a.size(); ++k)
                merged.push_back(a[(i + 1 + k) % a.size()]);
            for (std::size_t k = 2; k < b.size(); ++k)
                merged.push_back(b[(j + k) % b.size()]);
            return merged;
        }
    }
    return {};
}

} // namespace

double twiceSignedArea(const std::vector<Vec2>& polygon)
{
    double sum = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i)
    {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[(i + 1) % polygon.size()];
        sum += a.x * b.y - b.x * a.y;
    }
    return sum;
}

std::optional<EdgeCrossing> firstCrossing(const std::vector<Vec2>& polygon)
{
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
        {
            const Vec2& a = polygon[i];
            const Vec2& b = polygon[(i + 1) % n];
            const Vec2& c = polygon[j];
            const Vec2& d = polygon[(j + 1) % n];
            const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
            if (adjacent)
            {
                // Neighbours share a corner; they are wrong only when one folds back along the other.
                const Vec2& shared = j == i + 1 ? b : a;
                const Vec2& p = j == i + 1 ? a : b;
                const Vec2& q = j == i + 1 ? d : c;
                const double dot = (p.x - shared.x) * (q.x - shared.x) + (p.y - shared.y) * (q.y - shared.y);
                if (std::abs(cross(shared, p, q)) < 1e-12 && dot > 0)
                    return EdgeCrossing{i, j};
                continue;
            }
            if (segmentsMeet(a, b, c, d))
                return EdgeCrossing{i, j};
        }
    return std::nullopt;
}

std::vector<std::vector<Vec2>> convexPieces(std::vector<Vec2> polygon, std::size_t maxVertices)
{
    if (twiceSignedArea(polygon) < 0)
        std::reverse(polygon.begin(), polygon.end());
    // Drop repeated and collinear corners: they add nothing and make degenerate ears.
    for (std::size_t i = 0; i < polygon.size() && polygon.size() > 3;)
    {
        const std::size_t n = polygon.size();
        const Vec2& prev = polygon[(i + n - 1) % n];
        const Vec2& next = polygon[(i + 1) % n];
        if (polygon[i] == next || std::abs(cross(prev, polygon[i], next)) < 1e-12)
            polygon.erase(polygon.begin() + static_cast<std::ptrdiff_t>(i));
        else
            ++i;
    }
    std::vector<std::vector<Vec2>> pieces;
    if (polygon.size() <= maxVertices && convex(polygon))
    {
        pieces.push_back(polygon);
        return pieces;
    }
    // Ear clipping.
    std::vector<Vec2> rest = polygon;
    while (rest.size() > 3)
    {
        const std::size_t n = rest.size();
        bool clipped = false;
        for (std::size_t i = 0; i < n && !clipped; ++i)
        {
            const Vec2& a = rest[(i + n - 1) % n];
            const Vec2& b = rest[i];
            const Vec2& c = rest[(i + 1) % n];
            if (cross(a, b, c) <= 0)
                continue; // a reflex corner is no ear
            bool empty = true;
            for (std::size_t k = 0; k < n && empty; ++k)
                if (k != i && k != (i + n - 1) % n && k != (i + 1) % n && insideTriangle(rest[k], a, b, c))
                    empty = false;
            if (!empty)
                continue;
            pieces.push_back({a, b, c});
            rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
            clipped = true;
        }
        if (!clipped)
            return {}; // not simple after all
    }
    pieces.push_back(rest);
    // Merge neighbours while the union stays convex and small enough.
    for (bool merged = true; merged;)
    {
        merged = false;
        for (std::size_t i = 0; i < pieces.size() && !merged; ++i)
            for (std::size_t j = i + 1; j < pieces.size() && !merged; ++j)
            {
                std::vector<Vec2> joined = mergeAlongSharedEdge(pieces[i], pieces[j]);
                if (joined.empty() || joined.size() > maxVertices || !convex(joined))
                    continue;
                pieces[i] = std::move(joined);
                pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(j));
                merged = true;
            }
    }
    return pieces;
}

} // namespace abalike
