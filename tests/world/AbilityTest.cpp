#include <abalike/game/GameSession.hpp>
#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace abalike
{
namespace
{

/// A level with one bird of each kind and a wood tower 20 m away.
LevelDef abilityLevel(std::vector<std::string> birds)
{
    LevelDef level;
    level.birds = std::move(birds);
    for (int i = 0; i < 4; ++i)
        level.blocks.push_back({BlockShape::Box, "wood", 20.0, 0.5 + i, 0.5, 1.0, 0.0});
    level.pigs = {{"small", 21.0, 0.25}, {"small", 40.0, 0.25}};
    return level;
}

/// Launches the only bird and steps until `seconds` after launch.
void launchAndFly(GameSession& session, double angleDeg, double speedMps, double seconds)
{
    session.launch(angleDeg, speedMps);
    while (session.timeSinceLaunch() < seconds - 1e-9)
        session.step();
}

/// The bird's velocity over the last step, from its recorded path.
std::array<double, 2> pathVelocity(const ShotRecord& shot)
{
    const auto& a = shot.actualPath[shot.actualPath.size() - 2];
    const auto& b = shot.actualPath.back();
    return {(b[1] - a[1]) / (b[0] - a[0]), (b[2] - a[2]) / (b[0] - a[0])};
}

double angleOf(double x, double y)
{
    return std::atan2(y, x) * 180.0 / std::numbers::pi;
}

TEST(Abilities, SplitAddsTwoBirdsAtPlusMinusTheAngleAndLeavesTheBirdOnItsPredictedPath)
{
    GameSession session(abilityLevel({"blue"}));
    launchAndFly(session, 20.0, 20.0, 0.25);
    ASSERT_TRUE(session.canActivateAbility());
    ASSERT_TRUE(session.activateAbility());
    EXPECT_FALSE(session.canActivateAbility()) << "an ability is used once";
    EXPECT_EQ(session.world().projectilesInPlay(), 2);

    const ShotRecord& shot = session.shots().back();
    ASSERT_TRUE(shot.ability.has_value());
    EXPECT_EQ(shot.ability->ability, "split");
    EXPECT_TRUE(shot.ability->beforeContact);
    EXPECT_FALSE(shot.ability->changedFlight);
    ASSERT_EQ(shot.ability->impulses.size(), 2u);
    const double mass = session.catalog().findBird("blue")->massKg;
    const double split = session.catalog().abilities().splitAngleDeg;
    // The bird's own velocity now: the RK4 state the world flies it on.
    std::vector<double> offsets;
    for (const Entity& e : session.world().entities())
    {
        if (e.kind != EntityKind::Bird || !e.alive || &e == session.world().bird())
            continue;
        const b2Vec2 v = e.body->GetLinearVelocity();
        const AbilityImpulse& j = shot.ability->impulses[offsets.size()];
        EXPECT_NEAR(std::hypot(j.impulseX, j.impulseY), mass * v.Length(), 1e-4 * mass * v.Length());
        offsets.push_back(angleOf(v.x, v.y));
    }
    ASSERT_EQ(offsets.size(), 2u);
    EXPECT_NEAR(offsets[0] - offsets[1], 2.0 * split, 1e-3);

    while (session.phase() == Phase::Flying)
        session.step();
    ASSERT_TRUE(shot.deviationM.has_value()) << "a split does not change the bird's own flight";
    EXPECT_LT(*shot.deviationM, 0.01);
}

TEST(Abilities, BoostAddsItsSpeedAlongTheVelocity)
{
    GameSession session(abilityLevel({"yellow"}));
    launchAndFly(session, 30.0, 15.0, 0.3);
    const auto before = pathVelocity(session.shots().back());
    ASSERT_TRUE(session.activateAbility());
    session.step();
    const ShotRecord& shot = session.shots().back();
    const auto after = pathVelocity(shot);
    const double gain = session.catalog().abilities().boostSpeedGainMps;
    // One step of gravity and RK4 chord apart, the speed grew by the boost and the direction stayed.
    EXPECT_NEAR(std::hypot(after[0], after[1]) - std::hypot(before[0], before[1]), gain, 0.2);
    EXPECT_NEAR(angleOf(after[0], after[1]), angleOf(before[0], before[1]), 1.0);

    ASSERT_EQ(shot.ability->impulses.size(), 1u);
    const AbilityImpulse& j = shot.ability->impulses[0];
    const double mass = session.catalog().findBird("yellow")->massKg;
    EXPECT_NEAR(std::hypot(j.impulseX, j.impulseY), mass * gain, 1e-9);
    EXPECT_NEAR(angleOf(j.impulseX, j.impulseY), angleOf(before[0], before[1]), 1.0);
    EXPECT_TRUE(shot.ability->changedFlight);

    while (session.phase() == Phase::Flying)
        session.step();
    EXPECT_TRUE(shot.actualContact.has_value());
    EXPECT_FALSE(shot.deviationM.has_value()) << "the prediction was for the flight without the boost";
    EXPECT_EQ(shot.accuracyPoints, 0);
}

TEST(Abilities, ExplosionPushesAndDamagesWithLinearFalloff)
{
    const LevelDef level = abilityLevel({"black"});
    GameWorld world(level, Catalog::builtin());
    world.step();
    const BirdType& black = *Catalog::builtin().findBird("black");
    FlightModel model;
    model.massKg = black.massKg;
    world.launchBird(black, model, {18.5, 1.0, 1.0, 0.0}); // 1.5 m left of the tower
    std::vector<double> healthBefore;
    for (const Entity& e : world.entities())
        healthBefore.push_back(e.health);
    const std::optional<AbilityUse> use = world.activateAbility();
    ASSERT_TRUE(use.has_value());
    EXPECT_EQ(use->ability, "explode");
    EXPECT_EQ(world.bird(), nullptr) << "the bird is gone with the blast";

    const AbilityParams& params = Catalog::builtin().abilities();
    ASSERT_FALSE(use->impulses.empty());
    for (const AbilityImpulse& j : use->impulses)
    {
        const double d = std::hypot(j.x - use->x, j.y - use->y);
        EXPECT_LT(d, params.explodeRadiusM);
        EXPECT_NEAR(std::hypot(j.impulseX, j.impulseY), params.explodeImpulseNs * (1.0 - d / params.explodeRadiusM),
                    1e-3);
        // Radial: the impulse points away from the bird.
        EXPECT_GT(j.impulseX * (j.x - use->x) + j.impulseY * (j.y - use->y), 0.0);
    }
    // The two lowest wood blocks (centres 1.58 m away) took 118 N s each: more than wood's 60.
    EXPECT_FALSE(world.entities()[1].alive);
    EXPECT_FALSE(world.entities()[2].alive);
    // The far pig is untouched.
    EXPECT_EQ(world.entities().back().health, healthBefore.back());
}

TEST(Abilities, EggAndBirdGetEqualAndOppositeImpulses)
{
    GameSession session(abilityLevel({"white"}));
    launchAndFly(session, 45.0, 14.0, 0.4);
    const auto before = pathVelocity(session.shots().back());
    ASSERT_TRUE(session.activateAbility());
    const ShotRecord& shot = session.shots().back();
    ASSERT_EQ(shot.ability->impulses.size(), 2u);
    const AbilityImpulse& egg = shot.ability->impulses[0];
    const AbilityImpulse& bird = shot.ability->impulses[1];
    EXPECT_EQ(egg.target, "egg");
    EXPECT_EQ(bird.target, "bird");
    EXPECT_EQ(egg.impulseX + bird.impulseX, 0.0);
    EXPECT_EQ(egg.impulseY + bird.impulseY, 0.0);
    EXPECT_LT(egg.y, bird.y);
    EXPECT_EQ(session.world().projectilesInPlay(), 1);

    const AbilityParams& params = session.catalog().abilities();
    const double birdMass = session.catalog().findBird("white")->massKg;
    const Entity* eggEntity = nullptr;
    for (const Entity& e : session.world().entities())
        if (e.typeName == "egg")
            eggEntity = &e;
    ASSERT_NE(eggEntity, nullptr);
    EXPECT_NEAR(eggEntity->body->GetMass(), params.eggMassKg, 1e-4);
    session.step();
    const auto after = pathVelocity(shot);
    EXPECT_NEAR(after[1] - before[1], params.eggMassKg * params.eggPushSpeedMps / birdMass, 0.5);
    EXPECT_NEAR(after[0], before[0], 0.01);

    while (session.phase() == Phase::Flying)
        session.step();
    EXPECT_EQ(session.world().projectilesInPlay(), 0) << "the egg is cleared when the shot ends";
}

TEST(Abilities, FollowTheRules)
{
    GameSession session(abilityLevel({"red", "blue", "black"}));
    EXPECT_FALSE(session.activateAbility()) << "nothing to activate while aiming";
    launchAndFly(session, 30.0, 10.0, 0.2);
    EXPECT_FALSE(session.canActivateAbility()) << "red has no ability";
    while (session.phase() == Phase::Flying)
        session.step();

    // Split only in free flight: after the first contact it is too late.
    session.launch(-10.0, 8.0);
    while (session.world().birdInFreeFlight())
        session.step();
    EXPECT_FALSE(session.activateAbility());
    while (session.phase() == Phase::Flying)
        session.step();

    // Explode also after contact.
    session.launch(-10.0, 8.0);
    while (session.world().birdInFreeFlight())
        session.step();
    EXPECT_TRUE(session.activateAbility());
    EXPECT_FALSE(session.shots().back().ability->beforeContact);
}

TEST(Abilities, ScriptedShotsUseThemAtTheirTimeAndReplayIdentically)
{
    const LevelDef level = abilityLevel({"yellow", "white"});
    const std::vector<ScriptedShot> shots{{20.0, 15.0, 0.2}, {40.0, 14.0, 0.5}};
    const auto a = simulateShots(level, shots);
    const auto b = simulateShots(level, shots);
    ASSERT_EQ(a->shots().size(), 2u);
    for (std::size_t i = 0; i < 2; ++i)
    {
        ASSERT_TRUE(a->shots()[i].ability.has_value()) << i;
        EXPECT_NEAR(a->shots()[i].ability->tS, *shots[i].abilityAtS, 1.0 / 60.0) << i;
        EXPECT_EQ(a->shots()[i].actualPath, b->shots()[i].actualPath) << i;
    }
    EXPECT_EQ(a->score().total(), b->score().total());
    EXPECT_THROW(simulateShots(abilityLevel({"red"}), {{20.0, 15.0, 0.2}}), LaunchError);
}

} // namespace
} // namespace abalike
