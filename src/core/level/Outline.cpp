#include "level/Outline.hpp"

#include <abalike/level/PolygonPartition.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace abalike
{

namespace
{

Outline polygon(double x, double y, double angleDeg, std::vector<Vec2> local)
{
    const double a = angleDeg * std::numbers::pi / 180.0;
    const double c = std::cos(a);
    const double s = std::sin(a);
    Outline out;
    out.centre = {x, y};
    for (const Vec2& v : local)
        out.vertices.push_back({x + c * v.x - s * v.y, y + s * v.x + c * v.y});
    return out;
}

Outline box(double x, double y, double w, double h, double angleDeg)
{
    const double hw = w / 2;
    const double hh = h / 2;
    return polygon(x, y, angleDeg, {{-hw, -hh}, {hw, -hh}, {hw, hh}, {-hw, hh}});
}

/// Extent of an outline along a unit axis.
std::array<double, 2> project(const Outline& o, const Vec2& axis)
{
    if (o.isCircle())
    {
        const double c = o.centre.x * axis.x + o.centre.y * axis.y;
        return {c - o.radius, c + o.radius};
    }
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const Vec2& v : o.vertices)
    {
        const double d = v.x * axis.x + v.y * axis.y;
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
    return {lo, hi};
}

void addEdgeNormals(const Outline& o, std::vector<Vec2>& axes)
{
    for (std::size_t i = 0; i < o.vertices.size(); ++i)
    {
        const Vec2& p = o.vertices[i];
        const Vec2& q = o.vertices[(i + 1) % o.vertices.size()];
        const double dx = q.x - p.x;
        const double dy = q.y - p.y;
        const double length = std::hypot(dx, dy);
        if (length > 0.0)
            axes.push_back({dy / length, -dx / length});
    }
}

/// Axes from a circle's centre to every vertex of the other outline (or its centre): the one that separates
/// a circle from a polygon's corner is among them.
void addCircleAxes(const Outline& circle, const Outline& other, std::vector<Vec2>& axes)
{
    const std::vector<Vec2> targets = other.isCircle() ? std::vector<Vec2>{other.centre} : other.vertices;
    for (const Vec2& v : targets)
    {
        const double dx = v.x - circle.centre.x;
        const double dy = v.y - circle.centre.y;
        const double length = std::hypot(dx, dy);
        if (length > 0.0)
            axes.push_back({dx / length, dy / length});
    }
}

} // namespace

std::array<Vec2, 2> Outline::bounds() const
{
    if (isCircle())
        return {Vec2{centre.x - radius, centre.y - radius}, Vec2{centre.x + radius, centre.y + radius}};
    const auto x = project(*this, {1.0, 0.0});
    const auto y = project(*this, {0.0, 1.0});
    return {Vec2{x[0], y[0]}, Vec2{x[1], y[1]}};
}

std::vector<Outline> blockOutlines(const BlockDef& b)
{
    const double hw = b.widthM / 2;
    const double hh = b.heightM / 2;
    switch (b.shape)
    {
    case BlockShape::Box:
        return {box(b.x, b.y, b.widthM, b.heightM, b.angleDeg)};
    case BlockShape::Circle:
        return {circleOutline(b.x, b.y, hw)};
    case BlockShape::Triangle:
        // The world's right triangle: the right angle at the bottom left of the bounding box.
        return {polygon(b.x, b.y, b.angleDeg, {{-hw, -hh}, {hw, -hh}, {-hw, hh}})};
    case BlockShape::HollowBox:
    {
        // Top and bottom walls span the width, the side walls fit between them: a pig may sit in the hole.
        const double t = b.wallM;
        const double sh = hh - t;
        return {polygon(b.x, b.y, b.angleDeg, {{-hw, hh - t}, {hw, hh - t}, {hw, hh}, {-hw, hh}}),
                polygon(b.x, b.y, b.angleDeg, {{-hw, -hh}, {hw, -hh}, {hw, -hh + t}, {-hw, -hh + t}}),
                polygon(b.x, b.y, b.angleDeg, {{-hw, -sh}, {-hw + t, -sh}, {-hw + t, sh}, {-hw, sh}}),
                polygon(b.x, b.y, b.angleDeg, {{hw - t, -sh}, {hw, -sh}, {hw, sh}, {hw - t, sh}})};
    }
    default:
        return {};
    }
}

Outline terrainOutline(const TerrainDef& t)
{
    if (t.isPolygon())
    {
        Outline all;
        all.vertices = t.points;
        if (twiceSignedArea(all.vertices) < 0)
            std::reverse(all.vertices.begin(), all.vertices.end());
        return all;
    }
    return box(t.x, t.y, t.widthM, t.heightM, t.angleDeg);
}

std::vector<Outline> terrainOutlines(const TerrainDef& t)
{
    if (!t.isPolygon())
        return {terrainOutline(t)};
    std::vector<Outline> pieces;
    for (std::vector<Vec2>& piece : convexPieces(t.points))
    {
        Outline outline;
        outline.vertices = std::move(piece);
        pieces.push_back(std::move(outline));
    }
    return pieces;
}

Outline circleOutline(double x, double y, double radius)
{
    Outline out;
    out.centre = {x, y};
    out.radius = radius;
    return out;
}

double penetration(const Outline& a, const Outline& b)
{
    std::vector<Vec2> axes;
    addEdgeNormals(a, axes);
    addEdgeNormals(b, axes);
    if (a.isCircle())
        addCircleAxes(a, b, axes);
    if (b.isCircle())
        addCircleAxes(b, a, axes);
    if (axes.empty()) // concentric circles
        return a.radius + b.radius;
    double depth = std::numeric_limits<double>::infinity();
    for (const Vec2& axis : axes)
    {
        const auto pa = project(a, axis);
        const auto pb = project(b, axis);
        depth = std::min(depth, std::min(pa[1] - pb[0], pb[1] - pa[0]));
    }
    return depth;
}

} // namespace abalike
