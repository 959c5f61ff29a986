#include "edit/ConvexShape.hpp"

#include <abalike/world/Catalog.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace abalike
{

namespace
{

/// Overlaps shallower than this (m) are grazes: a block sliding along the one it rests on does not hit it.
constexpr double kGrazeM = 1e-9;

double cross(const Vec2& o, const Vec2& a, const Vec2& b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/// Convex hull, counter-clockwise, without collinear points (Andrew's monotone chain).
ConvexShape hull(std::vector<Vec2> points)
{
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3)
        return points;
    ConvexShape out(2 * points.size());
    std::size_t k = 0;
    for (const Vec2& p : points)
    {
        while (k >= 2 && cross(out[k - 2], out[k - 1], p) <= 0.0)
            --k;
        out[k++] = p;
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;)
    {
        while (k >= lower && cross(out[k - 2], out[k - 1], points[i]) <= 0.0)
            --k;
        out[k++] = points[i];
    }
    out.resize(k - 1);
    return out;
}

ConvexShape circle(double x, double y, double radius)
{
    ConvexShape out;
    for (int i = 0; i < kCircleSides; ++i)
    {
        // Quarter turns are set exactly: cos(pi / 2) is not 0 in floating point.
        double c = 0.0;
        double s = 0.0;
        switch ((4 * i) % kCircleSides == 0 ? 4 * i / kCircleSides : -1)
        {
        case 0:
            c = 1.0;
            break;
        case 1:
            s = 1.0;
            break;
        case 2:
            c = -1.0;
            break;
        case 3:
            s = -1.0;
            break;
        default:
            c = std::cos(2.0 * std::numbers::pi * i / kCircleSides);
            s = std::sin(2.0 * std::numbers::pi * i / kCircleSides);
        }
        out.push_back({x + radius * c, y + radius * s});
    }
    return out;
}

} // namespace

ConvexShape objectShape(const ObjectDef& def, const Catalog& catalog)
{
    if (const auto* block = std::get_if<BlockDef>(&def))
    {
        if (block->shape == BlockShape::Circle)
            return circle(block->x, block->y, block->widthM / 2.0);
        std::vector<Vec2> points;
        for (const Outline& piece : blockOutlines(*block))
            points.insert(points.end(), piece.vertices.begin(), piece.vertices.end());
        return hull(std::move(points));
    }
    if (const auto* pig = std::get_if<PigDef>(&def))
    {
        const PigType* type = catalog.findPig(pig->type);
        return type ? circle(pig->x, pig->y, type->radiusM) : ConvexShape{};
    }
    if (const auto* terrain = std::get_if<TerrainDef>(&def))
        return terrain->isPolygon() ? hull(terrain->points) : terrainOutline(*terrain).vertices; // hull: for picking
    return {};
}

std::array<Vec2, 2> shapeBounds(const ConvexShape& shape)
{
    Vec2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    Vec2 hi{-lo.x, -lo.y};
    for (const Vec2& v : shape)
    {
        lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)};
        hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
    }
    return {lo, hi};
}

bool shapeContains(const ConvexShape& shape, const Vec2& point)
{
    if (shape.size() < 3)
        return false;
    for (std::size_t i = 0; i < shape.size(); ++i)
        if (cross(shape[i], shape[(i + 1) % shape.size()], point) < 0.0)
            return false;
    return true;
}

std::optional<std::array<double, 2>> contactInterval(const ConvexShape& moving, const ConvexShape& fixed, const Vec2& u)
{
    if (moving.size() < 3 || fixed.size() < 3)
        return std::nullopt;
    // moving + t u meets fixed exactly when t u lies in the Minkowski difference fixed - moving, a convex polygon;
    // the answer is where the line through the origin along u crosses it.
    std::vector<Vec2> points;
    points.reserve(moving.size() * fixed.size());
    // The hull of all vertex differences is the difference polygon. Shapes here have at most kCircleSides vertices,
    // and only objects near the moving one are tested, so the simple construction is fast enough.
    for (const Vec2& f : fixed)
        for (const Vec2& m : moving)
            points.push_back({f.x - m.x, f.y - m.y});
    const ConvexShape difference = hull(std::move(points));
    if (difference.size() < 3)
        return std::nullopt;
    double t0 = -std::numeric_limits<double>::infinity();
    double t1 = std::numeric_limits<double>::infinity();
    double inner0 = t0;
    double inner1 = t1;
    for (std::size_t i = 0; i < difference.size(); ++i)
    {
        const Vec2& a = difference[i];
        const Vec2& b = difference[(i + 1) % difference.size()];
        const double ex = b.x - a.x;
        const double ey = b.y - a.y;
        const double length = std::hypot(ex, ey);
        const Vec2 n{ey / length, -ex / length}; // outward normal of a counter-clockwise polygon
        const double offset = n.x * a.x + n.y * a.y;
        const double along = n.x * u.x + n.y * u.y;
        // Inside this edge's half-plane: t along <= offset. The inner bounds use the half-plane shrunk by a graze.
        if (along == 0.0)
        {
            if (offset < kGrazeM)
                return std::nullopt; // the line runs along or outside this edge
            continue;
        }
        const double t = offset / along;
        const double inner = (offset - kGrazeM) / along;
        if (along > 0.0)
        {
            t1 = std::min(t1, t);
            inner1 = std::min(inner1, inner);
        }
        else
        {
            t0 = std::max(t0, t);
            inner0 = std::max(inner0, inner);
        }
    }
    if (!(inner0 < inner1))
        return std::nullopt;
    return std::array<double, 2>{t0, t1};
}

} // namespace abalike
