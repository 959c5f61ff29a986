#include "TestCatalog.hpp"

#include <abalike/game/GameSession.hpp>
#include <abalike/world/GameWorld.hpp>
#include <box2d/box2d.h>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

constexpr double kWallX = 20.0;    ///< centre of the wall
constexpr double kWallWidth = 0.2; ///< the issue's 0.2 m stone wall
constexpr double kWallHeight = 3.0;
constexpr double kContactTolerance = 0.015;

/// A level with a 0.2 m stone wall standing on the ground (dynamic) or built into it (static terrain).
LevelDef wallLevel(bool staticWall)
{
    LevelDef level;
    for (const BirdType& bird : Catalog::builtin().birds())
        level.birds.push_back(bird.name);
    level.pigs = {{"small", 40.0, 0.25}};
    level.slingshot.maxForceN = 1.0e5; // every bird as fast as the world allows
    if (staticWall)
        level.terrain.push_back({kWallX, kWallHeight / 2, kWallWidth, kWallHeight, 0.0, {}});
    else
        level.blocks.push_back({BlockShape::Box, "stone", kWallX, kWallHeight / 2, kWallWidth, kWallHeight, 0.0});
    return level;
}

/// Stone that cannot break, so whatever gets past the wall went through it.
const Catalog& unbreakableStone()
{
    static const Catalog catalog =
        test::catalogWith([](nlohmann::json& root) { test::materialIn(root, "stone")["strength_ns"] = 1e9; });
    return catalog;
}

/// Centre x of the wall now.
double wallX(const GameWorld& world)
{
    for (const Entity& e : world.entities())
        if ((e.kind == EntityKind::Block || e.kind == EntityKind::Terrain) && e.body != nullptr)
            return e.body->GetPosition().x;
    return kWallX;
}

struct Flight
{
    std::optional<ContactPoint> contact;
    double maxBirdMinusWallX = -1e9; ///< the bird's centre relative to the wall's; > 0 means it got through
    double launchSpeed = 0.0;
    int maxSubsteps = 0;
};

/// Flies a bird straight at the wall through GameWorld (no launch cap) and watches it for a second.
Flight flyAtWall(bool staticWall, const std::string& birdName, double speed, const WorldSettings& settings = {})
{
    const LevelDef level = wallLevel(staticWall);
    GameWorld world(level, unbreakableStone(), settings);
    const BirdType& bird = *unbreakableStone().findBird(birdName);
    FlightModel model;
    model.massKg = bird.massKg;
    world.launchBird(bird, model, {{0.0, 1.5}, {speed, 0.0}});
    Flight flight;
    flight.launchSpeed = speed;
    for (int i = 0; i < 90 && world.bird() != nullptr; ++i)
    {
        world.step();
        flight.maxSubsteps = std::max(flight.maxSubsteps, world.lastSubsteps());
        if (world.bird() != nullptr)
            flight.maxBirdMinusWallX =
                std::max(flight.maxBirdMinusWallX, world.bird()->body->GetPosition().x - wallX(world));
    }
    flight.contact = world.birdContact();
    return flight;
}

TEST(Tunneling, EveryBirdAtTheSlingshotsTopSpeedStopsAtTheWall)
{
    for (const bool staticWall : {false, true})
        for (const BirdType& bird : unbreakableStone().birds())
        {
            LevelDef level = wallLevel(staticWall);
            level.birds = {bird.name};
            GameSession session(level, unbreakableStone());
            const double speed = session.maxLaunchSpeed();
            session.launch(0.0, speed);
            double worst = -1e9;
            while (session.phase() == Phase::Flying)
            {
                session.step();
                if (session.world().bird() != nullptr)
                    worst = std::max(worst, session.world().bird()->body->GetPosition().x - wallX(session.world()));
            }
            const ShotRecord& record = session.shots().back();
            ASSERT_TRUE(record.actualContact.has_value()) << bird.name;
            // First contact on the wall's near face: centre one radius short of it (Box2D's time of impact lets
            // shapes meet 1 cm into their skins).
            EXPECT_NEAR(record.actualContact->x, kWallX - kWallWidth / 2 - bird.radiusM, kContactTolerance)
                << bird.name << " at " << speed << " m/s";
            EXPECT_LT(worst, 0.0) << bird.name << " at " << speed << " m/s got past the wall";
        }
}

TEST(Tunneling, AForcedFiveHundredMetresPerSecondIsSubSteppedAndStops)
{
    // Box2D moves a body at most b2_maxTranslation = 2 m per step (120 m/s at 60 Hz); the world splits the step
    // so that 500 m/s really is 500 m/s (8.3 m per step in 5 sub-steps) and the bullet's time of impact catches
    // the wall in the sub-step that reaches it.
    for (const bool staticWall : {false, true})
    {
        const Flight flight = flyAtWall(staticWall, "red", 500.0);
        ASSERT_TRUE(flight.contact.has_value());
        EXPECT_GE(flight.maxSubsteps, 5);
        EXPECT_NEAR(flight.contact->x, kWallX - kWallWidth / 2 - 0.25, kContactTolerance);
        const double flightTime = (kWallX - kWallWidth / 2 - 0.25) / 500.0;
        EXPECT_NEAR(flight.contact->t, flightTime, 1.0 / 60.0) << "arrived as if slower than 500 m/s";
        EXPECT_LT(flight.maxBirdMinusWallX, 0.0) << "got past the wall";
    }
}

TEST(Tunneling, WithoutSubStepsBox2dCapsTheSpeedButStillStopsTheBird)
{
    WorldSettings settings;
    settings.maxSubsteps = 1;
    const Flight flight = flyAtWall(false, "red", 500.0, settings);
    ASSERT_TRUE(flight.contact.has_value());
    EXPECT_LT(flight.maxBirdMinusWallX, 0.0);
    // It arrives at 2 m per step (120 m/s), not 500 m/s: the honest speed needs the sub-steps.
    const double distance = kWallX - kWallWidth / 2 - 0.25;
    EXPECT_GT(flight.contact->t, 0.9 * distance / (b2_maxTranslation * 60.0));
}

} // namespace
} // namespace abalike
