#include <abalike/level/PushApart.hpp>

#include "level/Outline.hpp"
#include <abalike/world/Catalog.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace abalike
{
namespace
{

/// No body is moved further than this, or than its own height: a post sunk its whole length into the post below it
/// (a designer's slip of a digit) still comes out.
constexpr double kFurthestM = 1.0;
constexpr double kStepM = 0.005; ///< the search for a free place steps this far

/// A movable body of the level: where it is and how to draw its outline at an offset.
struct Movable
{
    bool pig = false;
    std::size_t index = 0;
    double radiusM = 0.0; ///< pigs
    double bottomM = 0.0;
    double heightM = 0.0;
};

Vec2 centreOf(const LevelDef& level, const Movable& body)
{
    return body.pig ? Vec2{level.pigs[body.index].x, level.pigs[body.index].y}
                    : Vec2{level.blocks[body.index].x, level.blocks[body.index].y};
}

std::vector<Outline> outlinesAt(const LevelDef& level, const Movable& body, double dx, double dy)
{
    if (body.pig)
    {
        const PigDef& pig = level.pigs[body.index];
        return {circleOutline(pig.x + dx, pig.y + dy, body.radiusM)};
    }
    BlockDef block = level.blocks[body.index];
    block.x += dx;
    block.y += dy;
    return blockOutlines(block);
}

std::string pointerOf(const Movable& body)
{
    return (body.pig ? "/pigs/" : "/blocks/") + std::to_string(body.index);
}

/// What a body may not overlap: terrain, and the bodies already set.
struct Obstacle
{
    std::string pointer;
    Outline outline;
    double centreX = 0.0;
    double centreY = 0.0;
    double halfHeightM = 0.0;
};

/// The deepest overlap of outlines with the obstacles, and which obstacle it is with.
std::pair<double, const Obstacle*> deepest(const std::vector<Outline>& outlines, const std::vector<Obstacle>& obstacles)
{
    std::pair<double, const Obstacle*> worst{0.0, nullptr};
    for (const Outline& piece : outlines)
    {
        const auto [low, high] = piece.bounds();
        for (const Obstacle& obstacle : obstacles)
        {
            const auto [olow, ohigh] = obstacle.outline.bounds();
            if (ohigh.x < low.x || olow.x > high.x || ohigh.y < low.y || olow.y > high.y)
                continue;
            const double depth = penetration(piece, obstacle.outline);
            if (depth > worst.first)
                worst = {depth, &obstacle};
        }
    }
    return worst;
}

/// How far the body must move along direction to overlap none of the obstacles, in whole millimetres; none when
/// nothing within kFurthestM is free. The overlap's depth itself first, to the millimetre (lowered onto what is
/// below, a body is free at that one place only: touching), then kStepM steps (something further on may be in the
/// way again), then to a tenth of a millimetre.
std::optional<double> nearestFree(const LevelDef& level, const Movable& body, Vec2 direction,
                                  const std::vector<Obstacle>& obstacles, double depthM)
{
    const auto freeAt = [&](double t)
    {
        return deepest(outlinesAt(level, body, direction.x * t, direction.y * t), obstacles).first <= 1e-4;
    };
    for (const double t :
         {std::ceil(depthM * 1000.0 - 1e-6) / 1000.0, std::ceil(depthM * 1000.0 - 1e-6) / 1000.0 + 0.001})
        if (t > 0.0 && freeAt(t))
            return t;
    double hi = 0.0;
    const double furthest = std::max(kFurthestM, body.heightM + kStepM);
    for (double step = kStepM; step <= furthest + 1e-9 && hi == 0.0; step += kStepM)
        if (freeAt(step))
            hi = step;
    if (hi == 0.0)
        return std::nullopt;
    double lo = hi - kStepM;
    while (hi - lo > 1e-4)
        (freeAt(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
    return std::ceil(hi * 1000.0 - 1e-6) / 1000.0; // never less than needed
}

/// Whether the body, moved by (dx, dy), stands on something: the ground, or a body or terrain within a centimetre
/// under it.
bool supportedAt(const LevelDef& level, const Movable& body, double dx, double dy,
                 const std::vector<Obstacle>& obstacles)
{
    constexpr double kUnderM = 0.01;
    return body.bottomM + dy <= level.groundY + kUnderM ||
           deepest(outlinesAt(level, body, dx, dy - kUnderM), obstacles).first > 1e-4;
}

/// Which way and how far a body overlapping `with` moves out: lifted off what is below it, or pushed aside where
/// that is shorter and leaves it standing on something (a pig moved into a post, a block a few centimetres into the
/// pig beside it), or always from a neighbour whose centre is at its own height; lowered out of what is above it when
/// it cannot be lifted (a plank raised into the posts it carries, whose bottoms are lower now), never into the
/// ground; else aside. None when no way is free within reach.
std::optional<std::pair<double, Vec2>> wayOut(const LevelDef& level, const Movable& body, const Obstacle& with,
                                              double depth, const std::vector<Obstacle>& obstacles)
{
    const Vec2 centre = centreOf(level, body);
    const Vec2 aside{centre.x >= with.centreX ? 1.0 : -1.0, 0.0};
    const Vec2 up{0.0, 1.0};
    const Vec2 down{0.0, -1.0};
    const std::optional<double> sideways = nearestFree(level, body, aside, obstacles, depth);
    const bool beside = std::abs(centre.y - with.centreY) < 0.25 * std::min(body.heightM, 2.0 * with.halfHeightM);
    if (sideways && beside)
        return std::pair{*sideways, aside};
    const std::optional<double> lift = nearestFree(level, body, up, obstacles, depth);
    if (sideways && (!lift || *sideways < *lift) && supportedAt(level, body, aside.x * *sideways, 0.0, obstacles))
        return std::pair{*sideways, aside};
    if (lift)
        return std::pair{*lift, up};
    if (with.centreY > centre.y)
        if (const std::optional<double> lower = nearestFree(level, body, down, obstacles, depth);
            lower && body.bottomM - *lower >= level.groundY - 1e-9)
            return std::pair{*lower, down};
    if (sideways)
        return std::pair{*sideways, aside};
    return std::nullopt;
}

std::vector<Obstacle> terrainObstacles(const LevelDef& level)
{
    std::vector<Obstacle> obstacles;
    for (std::size_t i = 0; i < level.terrain.size(); ++i)
        for (Outline& piece : terrainOutlines(level.terrain[i]))
        {
            const auto [low, high] = piece.bounds();
            obstacles.push_back({"/terrain/" + std::to_string(i), std::move(piece), 0.5 * (low.x + high.x),
                                 0.5 * (low.y + high.y), 0.5 * (high.y - low.y)});
        }
    return obstacles;
}

} // namespace

std::vector<PushedBody> pushOutOfGround(LevelDef& level, const Catalog& catalog)
{
    std::vector<PushedBody> pushed;
    const auto lift = [&](const std::string& pointer, double bottom, double& y)
    {
        const double depth = level.groundY - bottom;
        if (depth <= 1e-9)
            return;
        const double dy = std::ceil(depth * 1000.0 - 1e-6) / 1000.0; // whole millimetres, never less than needed
        y = std::round((y + dy) * 1000.0) / 1000.0;
        pushed.push_back({pointer, "the ground", depth, 0.0, dy});
    };
    for (std::size_t i = 0; i < level.blocks.size(); ++i)
    {
        double bottom = 1e300;
        for (const Outline& piece : blockOutlines(level.blocks[i]))
            bottom = std::min(bottom, piece.bounds()[0].y);
        if (bottom < 1e300)
            lift("/blocks/" + std::to_string(i), bottom, level.blocks[i].y);
    }
    for (std::size_t i = 0; i < level.pigs.size(); ++i)
        if (const PigType* type = catalog.findPig(level.pigs[i].type))
            lift("/pigs/" + std::to_string(i), level.pigs[i].y - type->radiusM, level.pigs[i].y);
    return pushed;
}

double deepestOverlap(const LevelDef& level, const Catalog& catalog, bool pig, std::size_t index)
{
    std::vector<Obstacle> obstacles = terrainObstacles(level);
    std::vector<Outline> self;
    for (std::size_t i = 0; i < level.blocks.size(); ++i)
        for (Outline& piece : blockOutlines(level.blocks[i]))
        {
            if (!pig && i == index)
                self.push_back(std::move(piece));
            else
                obstacles.emplace_back().outline = std::move(piece);
        }
    for (std::size_t i = 0; i < level.pigs.size(); ++i)
        if (const PigType* type = catalog.findPig(level.pigs[i].type))
        {
            Outline circle = circleOutline(level.pigs[i].x, level.pigs[i].y, type->radiusM);
            if (pig && i == index)
                self.push_back(std::move(circle));
            else
                obstacles.emplace_back().outline = std::move(circle);
        }
    return deepest(self, obstacles).first;
}

std::vector<PushedBody> pushApartOverlaps(LevelDef& level, const Catalog& catalog, double toleranceM)
{
    std::vector<Obstacle> obstacles = terrainObstacles(level);
    std::vector<Movable> bodies;
    for (std::size_t i = 0; i < level.blocks.size(); ++i)
    {
        const std::vector<Outline> pieces = blockOutlines(level.blocks[i]);
        if (pieces.empty())
            continue;
        double low = 1e300, high = -1e300;
        for (const Outline& piece : pieces)
        {
            low = std::min(low, piece.bounds()[0].y);
            high = std::max(high, piece.bounds()[1].y);
        }
        bodies.push_back({false, i, 0.0, low, high - low});
    }
    for (std::size_t i = 0; i < level.pigs.size(); ++i)
        if (const PigType* type = catalog.findPig(level.pigs[i].type))
            bodies.push_back({true, i, type->radiusM, level.pigs[i].y - type->radiusM, 2.0 * type->radiusM});
    std::stable_sort(bodies.begin(), bodies.end(),
                     [](const Movable& a, const Movable& b) { return a.bottomM < b.bottomM; });

    std::vector<PushedBody> pushed;
    for (const Movable& body : bodies)
    {
        const auto [depth, with] = deepest(outlinesAt(level, body, 0.0, 0.0), obstacles);
        if (depth > toleranceM && with != nullptr)
        {
            const std::optional<std::pair<double, Vec2>> way = wayOut(level, body, *with, depth, obstacles);
            if (way)
            {
                const auto [t, direction] = *way;
                double& x = body.pig ? level.pigs[body.index].x : level.blocks[body.index].x;
                double& y = body.pig ? level.pigs[body.index].y : level.blocks[body.index].y;
                x = std::round((x + direction.x * t) * 1000.0) / 1000.0;
                y = std::round((y + direction.y * t) * 1000.0) / 1000.0;
                pushed.push_back({pointerOf(body), with->pointer, depth, direction.x * t, direction.y * t});
            }
        }
        for (Outline& piece : outlinesAt(level, body, 0.0, 0.0))
        {
            const auto [low, high] = piece.bounds();
            obstacles.push_back({pointerOf(body), std::move(piece), 0.5 * (low.x + high.x), 0.5 * (low.y + high.y),
                                 0.5 * (high.y - low.y)});
        }
    }
    return pushed;
}

} // namespace abalike
