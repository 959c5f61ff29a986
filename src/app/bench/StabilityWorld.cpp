#include "bench/StabilityWorld.hpp"

#include <abalike/flight/Prediction.hpp>
#include <abalike/world/GameWorld.hpp>

#include <algorithm>
#include <box2d/box2d.h>
#include <cmath>
#include <optional>
#include <sstream>

namespace abalike::app
{

namespace
{

constexpr double kWallX = 20.0;
constexpr double kWallWidthM = 0.2;
constexpr double kWallHeightM = 4.0;
/// Box2D lets shapes meet inside their skins (b2_polygonRadius 1 cm) and resolves overlaps up to b2_linearSlop.
constexpr double kPenetrationAllowanceM = 0.03;
/// Above 108 m/s the world splits a step into Box2D sub-steps, and Box2D begins a contact as soon as the skins
/// overlap at the start of a sub-step: up to 3 b2_linearSlop (1.5 cm) before the time-of-impact point that the
/// preview's one cast per step finds. Measured worst: 1.1 cm (black bird, 300 m/s).
constexpr double kDeviationLimitM = 0.02;

LevelDef wallLevel(bool staticWall, double gravity)
{
    LevelDef level;
    level.id = "stability-wall";
    level.environment.gravity = gravity;
    level.environment.airDensity = 1.2;
    level.slingshot.maxForceN = 1e9;
    if (staticWall)
        level.terrain.push_back({kWallX, kWallHeightM / 2, kWallWidthM, kWallHeightM, 0.0, {}});
    else
        level.blocks.push_back(
            {BlockShape::Box, "stone", kWallX, kWallHeightM / 2, kWallWidthM, kWallHeightM, 0.0, 0.1});
    level.pigs.push_back({"small", kWallX + 8.0, 0.25});
    return level;
}

/// The wall's body, if it still stands.
const b2Body* wallBody(const GameWorld& world)
{
    for (const Entity& e : world.entities())
        if ((e.kind == EntityKind::Block || e.kind == EntityKind::Terrain) && e.alive && e.body != nullptr)
            return e.body;
    return nullptr;
}

struct LaunchOutcome
{
    bool nonFinite = false;
    double penetrationM = 0.0;
    bool tunnelled = false;
    std::optional<double> deviationM; ///< when both the preview and the world found a first contact
    bool wallBroken = false;
};

/// Launches one bird and watches the world until a second after first contact (at most 15 s: a 0.1 g bird in air
/// falls at 0.13 m/s).
LaunchOutcome launch(const LevelDef& level, const BirdType& bird, double speed, double angleDeg)
{
    GameWorld world(level, Catalog::builtin());
    FlightModel model;
    model.gravity = level.environment.gravity;
    model.massKg = bird.massKg;
    model.quadraticDrag = quadraticDragCoefficient(level.environment.airDensity, bird.dragCoefficient, bird.radiusM);
    speed = std::min(speed, world.maxSpeedMps());
    const FlightState s0 = launchState(level.slingshot.x, level.slingshot.y, speed, angleDeg);

    // The preview exactly as GameSession::preview makes it.
    IntegratorSettings settings;
    settings.dtS = world.dt();
    PredictionLimits limits;
    limits.maxTimeS = 15.0;
    limits.contact = [&](const FlightState& a, const FlightState& b)
    {
        return world.castCircle(bird.radiusM, a, b);
    };
    const PredictedFlight predicted = predictFlight(model, settings, s0, limits);

    world.launchBird(bird, model, s0);
    LaunchOutcome outcome;
    const bool hadWall = wallBody(world) != nullptr;
    int afterContact = 0;
    b2Vec2 previous(static_cast<float>(s0.position.x), static_cast<float>(s0.position.y));
    for (int i = 0; i < 15 * 60 && afterContact < 60 && world.bird() != nullptr; ++i)
    {
        world.step();
        outcome.nonFinite |= world.hasNonFiniteState();
        if (world.birdContact())
            ++afterContact;
        const Entity* b = world.bird();
        if (b == nullptr || b->body == nullptr)
            break;
        const b2Vec2 p = b->body->GetPosition();
        if (const b2Body* wall = wallBody(world); wall != nullptr && std::abs(wall->GetAngle()) < 0.05f)
        {
            const double centre = wall->GetPosition().x;
            const double nearFace = centre - kWallWidthM / 2;
            // How deep the bird's leading edge is in the standing wall (only from the left, below its top).
            if (p.y < kWallHeightM && p.x < centre)
                outcome.penetrationM = std::max(outcome.penetrationM, p.x + bird.radiusM - nearFace);
            // Through it: this step's move crosses the wall's centre line below the top.
            if (previous.x < centre && p.x >= centre)
            {
                const double u = (centre - previous.x) / (p.x - previous.x);
                outcome.tunnelled |= previous.y + u * (p.y - previous.y) < kWallHeightM;
            }
        }
        else if (hadWall && wallBody(world) == nullptr)
            outcome.wallBroken = true;
        outcome.penetrationM = std::max(outcome.penetrationM, level.groundY - (p.y - bird.radiusM));
        outcome.tunnelled |= p.y < level.groundY;
        previous = p;
    }
    if (predicted.contact && world.birdContact())
        outcome.deviationM =
            std::hypot(predicted.contact->x - world.birdContact()->x, predicted.contact->y - world.birdContact()->y);
    return outcome;
}

std::string range(const std::vector<double>& values, const char* unit)
{
    std::ostringstream out;
    out << values.front() << " .. " << values.back() << ' ' << unit << ", " << values.size() << " values";
    return out.str();
}

void accumulate(WorldStabilityRow& row, const LaunchOutcome& outcome)
{
    ++row.runs;
    row.anyNonFinite |= outcome.nonFinite;
    row.worstPenetrationM = std::max(row.worstPenetrationM, outcome.penetrationM);
    row.tunnelled |= outcome.tunnelled;
    if (outcome.deviationM)
    {
        ++row.contactsCompared;
        row.worstDeviationM = std::max(row.worstDeviationM, *outcome.deviationM);
    }
    row.wallsBroken += outcome.wallBroken ? 1 : 0;
}

void finish(WorldStabilityRow& row)
{
    row.passed = !row.anyNonFinite && !row.tunnelled && row.worstPenetrationM <= kPenetrationAllowanceM &&
                 row.worstDeviationM <= kDeviationLimitM;
}

} // namespace

std::vector<WorldStabilityRow> runWorldStability(bool quick)
{
    std::vector<WorldStabilityRow> rows;
    const double maxSpeed = GameWorld(wallLevel(true, 9.81), Catalog::builtin()).maxSpeedMps();
    const std::vector<double> speeds =
        quick ? std::vector<double>{1, 60, 200, maxSpeed}
              : std::vector<double>{0, 1, 5, 20, 50, 100, 119, 150, 200, 300, 400, 600, maxSpeed};

    for (const bool staticWall : {true, false})
        for (const BirdType& bird : Catalog::builtin().birds())
        {
            WorldStabilityRow row;
            row.group = staticWall ? "static 0.2 m wall" : "stone block 0.2 m wall";
            row.launches = bird.name + " straight at the wall, " + range(speeds, "m/s");
            for (const double speed : speeds)
                accumulate(row, launch(wallLevel(staticWall, 9.81), bird, speed, 0.0));
            finish(row);
            rows.push_back(row);
            if (quick)
                break;
        }

    const BirdType& red = *Catalog::builtin().findBird("red");
    {
        const std::vector<double> angles =
            quick ? std::vector<double>{-90, 0, 90} : std::vector<double>{-90, -60, -30, -10, 0, 10, 30, 60, 90};
        WorldStabilityRow row;
        row.group = "launch angle";
        row.launches = "red at " + std::to_string(static_cast<int>(maxSpeed)) + " m/s, " + range(angles, "deg");
        for (const double angle : angles)
            accumulate(row, launch(wallLevel(true, 9.81), red, maxSpeed, angle));
        finish(row);
        rows.push_back(row);
    }
    for (const double g : {0.0, 0.01, 100.0})
    {
        WorldStabilityRow row;
        std::ostringstream name;
        name << "gravity " << g << " m/s^2";
        row.group = name.str();
        row.launches = "red at 20 m/s and the top speed, 0 and 30 deg";
        for (const double speed : {20.0, maxSpeed})
            for (const double angle : {0.0, 30.0})
                accumulate(row, launch(wallLevel(true, g), red, speed, angle));
        finish(row);
        rows.push_back(row);
    }
    for (const double mass : {1e-4, 1e4})
    {
        BirdType bird = red;
        bird.name = mass < 1 ? "0.1 g bird" : "10 t bird";
        bird.massKg = mass;
        for (const bool staticWall : {true, false})
        {
            WorldStabilityRow row;
            row.group = std::string("mass ") + (mass < 1 ? "1e-4" : "1e4") + " kg, " +
                        (staticWall ? "static wall" : "stone block wall");
            row.launches = bird.name + " at 20 m/s and the top speed, 0 deg";
            for (const double speed : {20.0, maxSpeed})
                accumulate(row, launch(wallLevel(staticWall, 9.81), bird, speed, 0.0));
            finish(row);
            rows.push_back(row);
        }
    }
    return rows;
}

} // namespace abalike::app
