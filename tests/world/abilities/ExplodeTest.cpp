#include "../TestCatalog.hpp"
#include "AbilityTestLevel.hpp"

#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

using namespace abalike::test;

TEST(Abilities, ExplosionPushesAndDamagesWithLinearFalloff)
{
    const LevelDef level = abilityLevel({"black"});
    GameWorld world(level, Catalog::builtin());
    world.step();
    const BirdType& black = *Catalog::builtin().findBird("black");
    FlightModel model;
    model.massKg = black.massKg;
    world.launchBird(black, model, {{18.5, 1.0}, {1.0, 0.0}}); // 1.5 m left of the tower
    std::vector<double> healthBefore;
    for (const Entity& e : world.entities())
        healthBefore.push_back(e.health);
    const std::optional<AbilityUse> use = world.activateAbility();
    ASSERT_TRUE(use.has_value());
    EXPECT_EQ(use->ability, "explode");
    EXPECT_EQ(world.bird(), nullptr) << "the bird is gone with the blast";

    const double radius = numberOf(Catalog::builtin(), "explode", "radius_m");
    const double impulse = numberOf(Catalog::builtin(), "explode", "impulse_ns");
    EXPECT_EQ(use->reachM, radius);
    ASSERT_FALSE(use->impulses.empty());
    for (const AbilityImpulse& j : use->impulses)
    {
        const double d = std::hypot(j.x - use->x, j.y - use->y);
        EXPECT_LT(d, radius);
        EXPECT_NEAR(std::hypot(j.impulseX, j.impulseY), impulse * (1.0 - d / radius), 1e-3);
        // Radial: the impulse points away from the bird.
        EXPECT_GT(j.impulseX * (j.x - use->x) + j.impulseY * (j.y - use->y), 0.0);
    }
    // The two lowest wood blocks (centres 1.58 m away) took 118 N s each: more than wood's 60.
    EXPECT_FALSE(world.entities()[1].alive);
    EXPECT_FALSE(world.entities()[2].alive);
    // The far pig is untouched.
    EXPECT_EQ(world.entities().back().health, healthBefore.back());
}

TEST(Abilities, TheBlackBirdsBlastBreaksStoneBesideIt)
{
    // A 1 m stone block and the bird exploding as it touches its side: the bird's centre 0.8 m from the block's.
    LevelDef level;
    level.birds = {"black"};
    level.blocks.push_back({BlockShape::Box, "stone", 10.0, 0.5, 1.0, 1.0, 0.0, 0.1});
    level.pigs = {{"small", 30.0, 0.25}};
    GameWorld world(level, Catalog::builtin());
    world.step();
    const BirdType& black = *Catalog::builtin().findBird("black");
    FlightModel model;
    model.massKg = black.massKg;
    world.launchBird(black, model, {{10.0 - 0.8, 0.5}, {0.0, 0.0}});
    ASSERT_TRUE(world.activateAbility().has_value());
    EXPECT_FALSE(world.entities()[1].alive) << "500 N s x (1 - 0.8 / 3) = 367 N s against stone's 300";
}

/// Launches and never taps: steps until the bird's fused ability went off. Returns how long after the shot's first
/// contact it did, none when it never did (or not by the fuse).
std::optional<double> untappedUntilItGoesOff(GameSession& session, double angleDeg, double speedMps)
{
    session.launch(angleDeg, speedMps);
    const double launchedAt = session.world().time() - session.timeSinceLaunch();
    while (session.phase() == Phase::Flying && !session.shots().back().ability)
        session.step();
    const ShotRecord& shot = session.shots().back();
    if (!shot.ability || !shot.ability->byFuse || !shot.contactTimeS)
        return std::nullopt;
    return shot.ability->tS - (*shot.contactTimeS - launchedAt);
}

TEST(Abilities, AnUntappedBlackBirdGoesOffByItselfAFuseAfterItsFirstContact)
{
    // Thrown flat into the wood tower and never tapped: 1.5 s after the bird first touched it (it breaks through
    // and rolls on), it blows up where it is, recorded as the shot's ability (by the fuse), and the next bird is still
    // ready 3 s after the contact.
    LevelDef level = abilityLevel({"black", "black"});
    GameSession session(level);
    const double fuse = numberOf(Catalog::builtin(), "explode", "fuse_s");
    ASSERT_EQ(fuse, 1.5);
    const std::optional<double> afterContact = untappedUntilItGoesOff(session, 10.0, 25.0);
    ASSERT_TRUE(afterContact.has_value());
    const ShotRecord& shot = session.shots().back();
    EXPECT_FALSE(shot.ability->beforeContact);
    EXPECT_NEAR(*afterContact, fuse, 1.0 / 60.0 + 1e-9);
    EXPECT_GT(shot.ability->x, 20.0) << "it broke through the tower and went off where it rolled to";
    EXPECT_EQ(session.world().bird(), nullptr) << "the bird is gone with the blast";
    while (session.phase() == Phase::Flying)
        session.step();
    ASSERT_TRUE(shot.readyAfterContactS.has_value());
    EXPECT_LE(*shot.readyAfterContactS, GameSession::kReadyAfterContactS + 1.0 / 60.0 + 1e-9);
}

TEST(Abilities, ABlackBirdThatComesToRestBeforeItsFuseGoesOffAsItStops)
{
    // Dropped onto the ground from 0.35 m with no speed: it rests within the fuse's time, and goes off as it would
    // otherwise leave with a puff, not later and not never.
    LevelDef level = abilityLevel({"black", "black"});
    GameSession session(level);
    const std::optional<double> afterContact = untappedUntilItGoesOff(session, 0.0, 0.5);
    ASSERT_TRUE(afterContact.has_value());
    EXPECT_LT(*afterContact, numberOf(Catalog::builtin(), "explode", "fuse_s") - 0.1);
}

TEST(Abilities, ATappedBlackBirdIsNotBlownUpTwice)
{
    LevelDef level = abilityLevel({"black", "black"});
    GameSession session(level);
    launchAndFly(session, 20.0, 16.0, 0.5);
    ASSERT_TRUE(session.activateAbility());
    EXPECT_FALSE(session.shots().back().ability->byFuse);
    const double usedAt = session.shots().back().ability->tS;
    while (session.phase() == Phase::Flying)
        session.step();
    EXPECT_EQ(session.shots().back().ability->tS, usedAt);
}

TEST(Abilities, ABodyTheBlastFlingsStopsAtAThinPlank)
{
    // A pig tough enough to survive the blast, 0.6 m from it, is sent off at about 68 m/s: more than a metre a step.
    // A 0.2 m stone plank, made too strong to break here, stands 4 m away. Swept as a bullet until it slows, the pig
    // stops at the plank instead of stepping through it.
    const Catalog catalog = test::catalogWith(
        [](nlohmann::json& root)
        {
            for (nlohmann::json& pig : root["pigs"])
                pig["health_ns"] = 5000.0;
            for (nlohmann::json& material : root["materials"])
                material["strength_ns"] = 1.0e6;
        });
    LevelDef level;
    level.birds = {"black"};
    level.pigs = {{"small", 5.6, 0.25}};
    level.blocks.push_back({BlockShape::Box, "stone", 9.6, 1.0, 0.2, 2.0, 0.0, 0.1});
    GameWorld world(level, catalog);
    world.step();
    const BirdType& black = *catalog.findBird("black");
    FlightModel model;
    model.massKg = black.massKg;
    world.launchBird(black, model, {{5.0, 0.25}, {0.0, 0.0}});
    ASSERT_TRUE(world.activateAbility().has_value());
    const b2Body* pig = world.entities()[2].body;
    ASSERT_NE(pig, nullptr);
    EXPECT_GT(pig->GetLinearVelocity().x, 50.0f) << "the blast should fling it fast";
    EXPECT_TRUE(pig->IsBullet());
    for (int i = 0; i < 60; ++i)
        world.step();
    ASSERT_TRUE(world.entities()[2].alive);
    EXPECT_LT(world.entities()[2].body->GetPosition().x, 9.6f) << "the pig passed through the plank";
    EXPECT_FALSE(world.entities()[2].body->IsBullet()) << "slowed down: an ordinary body again";
}

} // namespace
} // namespace abalike
