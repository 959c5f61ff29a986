#include "level/LevelSections.hpp"
#include "level/Outline.hpp"
#include "level/Reach.hpp"
#include <abalike/level/LevelLimits.hpp>

#include <abalike/level/LevelFlight.hpp>
#include <abalike/world/BirdBody.hpp>
#include <abalike/world/Catalog.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace abalike
{

namespace
{

using namespace abalike::limits;

/// A bird stays in play this long after launch (GameSession's bird lifetime): paths longer than that do not count.
constexpr double kBirdLifetimeS = 12.0;

/// A body of the level with its outline and where it is in the file.
struct Body
{
    std::string pointer;
    Outline outline;
    bool isStatic = false;
};

/// The radius the world collides a bird with (a tiny custom bird collides as a larger ball).
double collisionRadius(const BirdType& bird)
{
    return birdCollisionBody(bird, 0.0).radiusM;
}

std::string metres(double value)
{
    std::ostringstream out;
    out << std::round(value * 1000.0) / 1000.0 << " m";
    return out.str();
}

std::vector<Body> collectBodies(const LevelDef& level, const Catalog& catalog)
{
    std::vector<Body> bodies;
    for (std::size_t i = 0; i < level.terrain.size(); ++i)
        for (Outline& piece : terrainOutlines(level.terrain[i]))
            bodies.push_back({"/terrain/" + std::to_string(i), std::move(piece), true});
    for (std::size_t i = 0; i < level.blocks.size(); ++i)
        for (Outline& piece : blockOutlines(level.blocks[i]))
            bodies.push_back({"/blocks/" + std::to_string(i), std::move(piece), false});
    for (std::size_t i = 0; i < level.pigs.size(); ++i)
    {
        const PigDef& pig = level.pigs[i];
        if (const PigType* type = catalog.findPig(pig.type))
            bodies.push_back({"/pigs/" + std::to_string(i), circleOutline(pig.x, pig.y, type->radiusM), false});
    }
    return bodies;
}

/// Interpenetrating bodies: Box2D would push them apart with a jolt at the first step. Static terrain may overlap
/// other terrain (hills are built from pieces).
void checkOverlaps(const std::vector<Body>& bodies, LevelReader& r)
{
    // Sweep and prune along x, so a large level stays fast.
    std::vector<std::size_t> order(bodies.size());
    std::vector<std::array<Vec2, 2>> box(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
        order[i] = i;
        box[i] = bodies[i].outline.bounds();
    }
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b)
              { return box[a][0].x < box[b][0].x || (box[a][0].x == box[b][0].x && a < b); });
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t m = 0; m < order.size(); ++m)
        for (std::size_t n = m + 1; n < order.size() && box[order[n]][0].x <= box[order[m]][1].x; ++n)
        {
            const std::size_t a = std::min(order[m], order[n]);
            const std::size_t b = std::max(order[m], order[n]);
            if (box[a][0].y > box[b][1].y || box[b][0].y > box[a][1].y)
                continue;
            if ((bodies[a].isStatic && bodies[b].isStatic) || bodies[a].pointer == bodies[b].pointer)
                continue;
            pairs.emplace_back(a, b);
        }
    // Report in file order, whatever the sweep found first.
    std::sort(pairs.begin(), pairs.end(),
              [](const auto& p, const auto& q) { return std::tie(p.second, p.first) < std::tie(q.second, q.first); });
    std::set<std::pair<std::string, std::string>> reported; // a hollow box's walls are one body
    for (const auto& [a, b] : pairs)
    {
        const double depth = penetration(bodies[a].outline, bodies[b].outline);
        if (depth > kOverlapToleranceM && reported.emplace(bodies[a].pointer, bodies[b].pointer).second)
            r.error(bodies[b].pointer, "overlaps " + bodies[a].pointer + " (expected bodies to touch at most, got " +
                                           metres(depth) + " of overlap)");
    }
}

/// Moving bodies must start above the ground and every body inside the world.
void checkBounds(const LevelDef& level, const std::vector<Body>& bodies, LevelReader& r)
{
    std::set<std::string> reported; // once per body, however many pieces it has
    for (const Body& body : bodies)
    {
        const auto [lo, hi] = body.outline.bounds();
        const double reach = std::max({-lo.x, hi.x, -lo.y, hi.y});
        const bool beyond = reach > kWorldExtentM;
        const bool below = !body.isStatic && lo.y < level.groundY - kOverlapToleranceM;
        if ((beyond || below) && !reported.insert(body.pointer).second)
            continue;
        if (beyond)
            r.error(body.pointer, "reaches beyond the world bounds (expected within " + metres(kWorldExtentM) +
                                      " of the origin, got " + metres(reach) + ")");
        else if (below)
            r.error(body.pointer, "reaches below the ground (expected its bottom at y >= " + metres(level.groundY) +
                                      ", got " + metres(lo.y) + ")");
    }
}

/// The bird must leave the slingshot in the open: its circle at the launch point must not be inside anything.
void checkSlingshot(const LevelDef& level, const Catalog& catalog, const std::vector<Body>& bodies, LevelReader& r)
{
    double radius = 0.0;
    std::string widest;
    for (const std::string& name : level.birds)
        if (const BirdType* bird = catalog.findBird(name); bird && collisionRadius(*bird) > radius)
        {
            radius = collisionRadius(*bird);
            widest = name;
        }
    const Outline pouch = circleOutline(level.slingshot.x, level.slingshot.y, radius);
    if (level.slingshot.y - radius < level.groundY - kOverlapToleranceM)
        r.error("/slingshot/y", "the bird would start in the ground (expected y >= " + metres(level.groundY + radius) +
                                    " for the " + widest + " bird, got " + metres(level.slingshot.y) + ")");
    std::set<std::string> reported;
    for (const Body& body : bodies)
    {
        const double depth = penetration(pouch, body.outline);
        if (depth > kOverlapToleranceM && reported.insert(body.pointer).second)
            r.error("/slingshot", "the launch point is inside " + body.pointer + " (expected the " + widest +
                                      " bird, radius " + metres(radius) + ", to start clear of it, got " +
                                      metres(depth) + " of overlap)");
    }
}

/// Pigs above every path a launch can take: no shot reaches them, whatever the aim.
void checkReach(const LevelDef& level, const Catalog& catalog, LevelReader& r)
{
    std::vector<double> xs;
    double floorY = level.groundY;
    for (const PigDef& pig : level.pigs)
    {
        xs.push_back(pig.x);
        floorY = std::min(floorY, pig.y - 1.0);
    }
    // Every kind of bird the level has: the lightest is fastest, but drag may favour a heavier one.
    std::vector<std::string> kinds = level.birds;
    std::sort(kinds.begin(), kinds.end());
    kinds.erase(std::unique(kinds.begin(), kinds.end()), kinds.end());
    std::vector<std::optional<double>> best(xs.size());
    double farthest = level.slingshot.x;
    double fastest = 0.0;
    double birdRadius = 0.0;
    for (const std::string& name : kinds)
    {
        const BirdType* bird = catalog.findBird(name);
        if (bird == nullptr)
            continue;
        const double speed = maxLaunchSpeed(level, *bird, catalog);
        fastest = std::max(fastest, speed);
        birdRadius = std::max(birdRadius, collisionRadius(*bird));
        const ReachEnvelope envelope = reachEnvelope(levelFlightModel(level.environment, *bird), level.slingshot.x,
                                                     level.slingshot.y, speed, xs, floorY, kBirdLifetimeS);
        farthest = std::max(farthest, envelope.farthestX);
        for (std::size_t i = 0; i < xs.size(); ++i)
            if (envelope.highestY[i] && (!best[i] || *envelope.highestY[i] > *best[i]))
                best[i] = envelope.highestY[i];
    }
    for (std::size_t i = 0; i < level.pigs.size(); ++i)
    {
        const PigType* type = catalog.findPig(level.pigs[i].type);
        const double pigBottom = level.pigs[i].y - (type ? type->radiusM : 0.0) - birdRadius;
        std::ostringstream message;
        message.precision(4);
        if (!best[i])
            message << "out of the slingshot's reach (expected x within the farthest any launch gets, "
                    << metres(farthest) << " at " << fastest << " m/s, got x = " << metres(level.pigs[i].x) << ")";
        else if (*best[i] < pigBottom)
            message << "out of the slingshot's reach (expected y below the highest any launch passes over x = "
                    << metres(level.pigs[i].x) << ", " << metres(*best[i]) << ", got y = " << metres(level.pigs[i].y)
                    << ")";
        else
            continue;
        r.error("/pigs/" + std::to_string(i), message.str());
    }
}

void checkReferenceShot(const LevelDef& level, const Catalog& catalog, LevelReader& r)
{
    if (!level.referenceShot || level.birds.empty())
        return;
    const BirdType* bird = catalog.findBird(level.birds.front());
    if (bird == nullptr)
        return;
    const double top = maxLaunchSpeed(level, *bird, catalog);
    if (level.referenceShot->speedMps > top * (1.0 + 1e-12))
    {
        std::ostringstream message;
        message << "faster than the first bird (" << bird->name << ") can be launched (expected at most " << top
                << " m/s, got " << level.referenceShot->speedMps << ")";
        r.error("/reference_shot/1", message.str());
    }
}

} // namespace

void checkLevel(const LevelDef& level, const Catalog& catalog, LevelReader& r)
{
    const std::vector<Body> bodies = collectBodies(level, catalog);
    checkBounds(level, bodies, r);
    checkOverlaps(bodies, r);
    checkSlingshot(level, catalog, bodies, r);
    checkReach(level, catalog, r);
    checkReferenceShot(level, catalog, r);
}

} // namespace abalike
