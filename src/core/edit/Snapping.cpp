#include "edit/ConvexShape.hpp"

#include <abalike/edit/Snapping.hpp>
#include <abalike/world/Catalog.hpp>

#include <algorithm>
#include <cmath>

namespace abalike
{

namespace
{

/// A surface the moving object can meet: an object of the level, or the ground (no ref).
struct Contact
{
    double distance = 0.0; ///< how far the object moves along the direction to touch it (negative: back out)
    std::optional<ObjectRef> ref;
};

/// Every block, pig and terrain piece other than the ignored ones, with its shape.
std::vector<std::pair<ObjectRef, ConvexShape>> obstacles(const LevelDef& level, const Catalog& catalog,
                                                         const std::vector<ObjectRef>& ignore)
{
    std::vector<std::pair<ObjectRef, ConvexShape>> out;
    const auto add = [&](ObjectKind kind, std::size_t count)
    {
        for (std::size_t i = 0; i < count; ++i)
        {
            const ObjectRef ref{kind, i};
            if (std::find(ignore.begin(), ignore.end(), ref) != ignore.end())
                continue;
            ConvexShape shape = objectShape(objectDef(level, ref), catalog);
            if (!shape.empty())
                out.emplace_back(ref, std::move(shape));
        }
    };
    add(ObjectKind::Block, level.blocks.size());
    add(ObjectKind::Pig, level.pigs.size());
    add(ObjectKind::Terrain, level.terrain.size());
    return out;
}

ConvexShape shifted(const ConvexShape& shape, double dx, double dy)
{
    ConvexShape out = shape;
    for (Vec2& v : out)
    {
        v.x += dx;
        v.y += dy;
    }
    return out;
}

/// The nearest surface along u: the smallest distance at which the moving shape first touches something it is not
/// already past. The ground counts for downward moves.
std::optional<Contact> nearest(const ConvexShape& moving, const std::vector<std::pair<ObjectRef, ConvexShape>>& others,
                               const Vec2& u, std::optional<double> groundY)
{
    std::optional<Contact> best;
    const auto [lo, hi] = shapeBounds(moving);
    if (groundY)
        best = Contact{lo.y - *groundY, std::nullopt};
    for (const auto& [ref, shape] : others)
    {
        // Only shapes beside the moving one across the direction can be met; a quick test before the exact one.
        const auto [olo, ohi] = shapeBounds(shape);
        const int across = u.x == 0.0 ? 0 : 1;
        if (coordinate(ohi, across) <= coordinate(lo, across) || coordinate(olo, across) >= coordinate(hi, across))
            continue;
        const auto interval = contactInterval(moving, shape, u);
        if (!interval || (*interval)[1] <= 0.0)
            continue; // never met, or entirely behind
        if (!best || (*interval)[0] < best->distance)
            best = Contact{(*interval)[0], ref};
    }
    return best;
}

} // namespace

double cleanMetres(double value)
{
    return std::round(value * 1e9) / 1e9 + 0.0; // never -0 (a body mirrored about x = 0 shows "0.0", not "-0.0")
}

double snapAngle(double angleDeg, double stepDeg)
{
    const double snapped = stepDeg > 0.0 ? std::round(angleDeg / stepDeg) * stepDeg : angleDeg;
    return std::round(snapped * 1e9) / 1e9;
}

SnapResult snapObject(const LevelDef& level, const Catalog& catalog, const ObjectDef& def,
                      const std::vector<ObjectRef>& ignore, const SnapSettings& settings)
{
    const auto [x0, y0] = centreOf(def);
    SnapResult result{x0, y0, false, std::nullopt, std::nullopt};
    ConvexShape shape = objectShape(def, catalog);
    if (shape.empty())
    {
        // The slingshot (or an unknown pig type): its point on the grid.
        if (settings.grid && settings.gridM > 0.0)
        {
            result.x = cleanMetres(std::round(x0 / settings.gridM) * settings.gridM);
            result.y = cleanMetres(std::round(y0 / settings.gridM) * settings.gridM);
        }
        return result;
    }
    double dx = 0.0;
    double dy = 0.0;
    if (settings.grid && settings.gridM > 0.0)
    {
        // The lower-left corner on the grid: blocks whose sizes are grid multiples then line up edge to edge.
        const auto [lo, hi] = shapeBounds(shape);
        dx = std::round(lo.x / settings.gridM) * settings.gridM - lo.x;
        dy = std::round(lo.y / settings.gridM) * settings.gridM - lo.y;
    }
    if (settings.surfaces)
    {
        const auto others = obstacles(level, catalog, ignore);
        // Blocks and pigs stand on the ground, never in it: one put below the ground line comes up onto it, however
        // deep. Terrain may sink into the ground (hills are built that way).
        const bool floored = kindOf(def) != ObjectKind::Terrain;
        // Downwards a surface pulls from at least one grid step away: the grid may have lifted the body by up to half
        // a step, and a body put down a step above what is under it is meant to stand on it (a TNT crate left 25 cm
        // up by the grid was saved floating).
        const double downReach = settings.grid && settings.gridM > 0.0
                                     ? std::max(settings.surfaceReachM, settings.gridM)
                                     : settings.surfaceReachM;
        const auto settle = [&]
        {
            const auto below = nearest(shifted(shape, dx, dy), others, {0.0, -1.0}, level.groundY);
            if (!below)
                return;
            const bool underGround = floored && !below->ref && below->distance < 0.0;
            if (std::abs(below->distance) > downReach && !underGround)
                return;
            dy -= below->distance;
            result.onGround = !below->ref;
            result.restsOn = below->ref;
        };
        settle();
        const ConvexShape placed = shifted(shape, dx, dy);
        const auto left = nearest(placed, others, {-1.0, 0.0}, std::nullopt);
        const auto right = nearest(placed, others, {1.0, 0.0}, std::nullopt);
        const bool useLeft = left && std::abs(left->distance) <= settings.surfaceReachM &&
                             (!right || std::abs(left->distance) <= std::abs(right->distance));
        const bool useRight = !useLeft && right && std::abs(right->distance) <= settings.surfaceReachM;
        if (useLeft || useRight)
        {
            dx += useLeft ? -left->distance : right->distance;
            result.touchesSide = useLeft ? left->ref : right->ref;
            settle();
        }
    }
    // Exact contact arithmetic first, then one rounding: a stack's surfaces stay equal after cleaning because the
    // designed sizes are clean decimals themselves.
    result.x = cleanMetres(x0 + dx);
    result.y = cleanMetres(y0 + dy);
    return result;
}

} // namespace abalike
