#include "edit/EditHelpers.hpp"

#include <abalike/level/LevelLimits.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace abalike
{

void fitPolygonBounds(TerrainDef& terrain)
{
    double left = 1e300, right = -1e300, bottom = 1e300, top = -1e300;
    for (const auto& point : terrain.points)
    {
        left = std::min(left, point.x);
        right = std::max(right, point.x);
        bottom = std::min(bottom, point.y);
        top = std::max(top, point.y);
    }
    terrain.x = 0.5 * (left + right);
    terrain.y = 0.5 * (bottom + top);
    terrain.widthM = right - left;
    terrain.heightM = top - bottom;
    terrain.angleDeg = 0.0;
}

bool polygonContains(const std::vector<Vec2>& points, double x, double y)
{
    bool inside = false;
    for (std::size_t i = 0, j = points.size() - 1; i < points.size(); j = i++)
    {
        const auto& a = points[i];
        const auto& b = points[j];
        if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x)
            inside = !inside;
    }
    return inside;
}

/// Turns a terrain polygon's points about its bounding box's centre; its box follows (a polygon has no angle).
void rotatePolygon(TerrainDef& terrain, double deltaDeg)
{
    const double c = std::cos(deltaDeg * std::numbers::pi / 180.0);
    const double s = std::sin(deltaDeg * std::numbers::pi / 180.0);
    for (auto& point : terrain.points)
    {
        const double dx = point.x - terrain.x;
        const double dy = point.y - terrain.y;
        point = {terrain.x + c * dx - s * dy, terrain.y + s * dx + c * dy};
    }
    fitPolygonBounds(terrain);
}

double clampCoordinate(double value)
{
    return std::clamp(cleanMetres(value), -limits::kWorldExtentM, limits::kWorldExtentM);
}

/// Angles are kept in (-180, 180] so that turning never leaves the format's -360..360.
double normaliseAngle(double degrees)
{
    double a = std::fmod(degrees, 360.0);
    if (a > 180.0)
        a -= 360.0;
    else if (a <= -180.0)
        a += 360.0;
    // + 0.0 turns the -0 of a mirrored square block into 0, which the panels show as "0.0", never "-0.0".
    return std::round(a * 1e9) / 1e9 + 0.0;
}

std::string plural(std::size_t count, const char* what)
{
    return std::to_string(count) + " " + what + (count == 1 ? "" : "s");
}

std::string labelFor(const char* verb, std::size_t count)
{
    return std::string(verb) + " " + plural(count, "object");
}

/// Bounds of an object for rectangle selection: its shape's, or the slingshot's point.
std::array<Vec2, 2> objectBounds(const ObjectDef& def, const Catalog& catalog)
{
    const ConvexShape shape = objectShape(def, catalog);
    if (!shape.empty())
        return shapeBounds(shape);
    const auto c = centreOf(def);
    return {Vec2{c.x, c.y}, Vec2{c.x, c.y}};
}

} // namespace abalike
