#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelCatalog.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/world/BirdBody.hpp>
#include <abalike/world/GameWorld.hpp>

#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

/// A wood box, a stone box and a pig, on Earth in air.
LevelDef scene()
{
    LevelDef level;
    level.id = "s";
    level.title = "s";
    level.birds = {"red"};
    level.blocks = {{BlockShape::Box, "wood", 20.0, 0.5, 1.0, 1.0, 0.0, 0.1},
                    {BlockShape::Box, "stone", 24.0, 0.5, 1.0, 1.0, 0.0, 0.1}};
    level.pigs = {{"small", 22.0, 0.25}};
    level.environment.airDensity = 1.2;
    level.environment.windX = -3.0;
    return level;
}

const b2Body* bodyOf(const GameWorld& world, EntityKind kind, int index)
{
    for (const Entity& e : world.entities())
        if (e.kind == kind && e.defIndex == index)
            return e.body;
    return nullptr;
}

TEST(SceneOverrides, MaterialValuesReachTheWorld)
{
    LevelDef level = scene();
    level.materials = {{"wood", 700.0, 0.25, 0.6, 90.0}};
    const GameWorld world(level, Catalog::builtin());
    const b2Body* wood = bodyOf(world, EntityKind::Block, 0);
    const b2Body* stone = bodyOf(world, EntityKind::Block, 1);
    // 700 kg/m^3 x 0.1 m slab x 1 m^2; stone keeps the catalog's 240 kg/m^2.
    EXPECT_NEAR(wood->GetMass(), 70.0, 1e-3);
    EXPECT_NEAR(stone->GetMass(), 240.0, 1e-2);
    EXPECT_FLOAT_EQ(wood->GetFixtureList()->GetFriction(), 0.25f);
    EXPECT_FLOAT_EQ(wood->GetFixtureList()->GetRestitution(), 0.6f);
    EXPECT_FLOAT_EQ(stone->GetFixtureList()->GetFriction(), 0.7f);
    for (const Entity& e : world.entities())
    {
        if (e.kind == EntityKind::Block)
        {
            EXPECT_EQ(e.maxHealth, e.typeName == "wood" ? 90.0 : 300.0);
        }
    }
    // The session, the checks and the solver read the same table.
    const GameSession session(level);
    EXPECT_EQ(session.catalog().findMaterial("wood")->densityKgPerM2, 70.0);
    EXPECT_EQ(session.catalog().findMaterial("wood")->bulkDensityKgPerM3, 700.0);
}

TEST(SceneOverrides, AbsentValuesKeepTheCatalogs)
{
    LevelDef level = scene();
    level.materials = {{"stone", std::nullopt, 0.9, std::nullopt, std::nullopt}};
    const Catalog table = levelCatalog(level, Catalog::builtin());
    const Material& stone = *table.findMaterial("stone");
    const Material& original = *Catalog::builtin().findMaterial("stone");
    EXPECT_EQ(stone.friction, 0.9);
    EXPECT_EQ(stone.densityKgPerM2, original.densityKgPerM2);
    EXPECT_EQ(stone.restitution, original.restitution);
    EXPECT_EQ(stone.strengthNs, original.strengthNs);
}

TEST(SceneOverrides, ACustomBirdFliesWithItsOwnMassSizeAndDrag)
{
    LevelDef level = scene();
    level.customBird = CustomBirdDef{10.0, 0.6, 0.3};
    level.birds = {kCustomBirdName, "red"};
    GameSession session(level);
    const BirdType* bird = session.currentBird();
    ASSERT_NE(bird, nullptr);
    EXPECT_EQ(bird->name, "custom");
    EXPECT_EQ(bird->massKg, 10.0);
    EXPECT_EQ(bird->radiusM, 0.3);
    // Earth's band: v0 = sqrt(F x / (m + m_b)) = 26.0 m/s.
    EXPECT_DOUBLE_EQ(session.maxLaunchSpeed(), std::sqrt(8100.0 * 2.0 / (10.0 + 14.0)));
    const FlightModel model = session.flightModelFor(*bird);
    EXPECT_DOUBLE_EQ(model.quadraticDrag, 0.5 * 1.2 * 0.3 * M_PI * 0.09);
    EXPECT_EQ(model.massKg, 10.0);
}

TEST(SceneOverrides, PreviewAndWorldAgreeForACustomBirdOnOverriddenMaterials)
{
    LevelDef level = scene();
    level.customBird = CustomBirdDef{2.5, 0.4, 0.8};
    level.birds = {kCustomBirdName};
    level.materials = {{"wood", 900.0, 0.3, 0.1, 40.0}};
    level.slingshot.maxForceN = 2000;
    level.slingshot.bandMassKg = 0.0; // a massless band: 40 m/s for the 2.5 kg bird
    for (const ScriptedShot shot : {ScriptedShot{20, 30}, {35, 25}, {45, 22}, {10, 40}})
    {
        const auto session = simulateShots(level, {shot});
        const ShotRecord& record = session->shots()[0];
        ASSERT_TRUE(record.deviationM) << shot.angleDeg;
        EXPECT_LT(*record.deviationM, 1e-4) << shot.angleDeg << "," << shot.speedMps;
    }
}

TEST(SceneOverrides, BirdBodiesAreClampedOnlyWhereBox2DNeedsIt)
{
    const BirdType& red = *Catalog::builtin().findBird("red");
    const BirdBody normal = birdCollisionBody(red, 2.5);
    EXPECT_FALSE(normal.clamped());
    EXPECT_EQ(describeBirdBody(normal), "");

    BirdType tiny = customBirdType(CustomBirdDef{0.01, 0.01, 0.47});
    const BirdBody small = birdCollisionBody(tiny, 2.5);
    EXPECT_EQ(small.radiusM, kMinBirdBodyRadiusM);
    EXPECT_EQ(small.massKg, 0.01) << "a light bird keeps its mass";
    EXPECT_NE(describeBirdBody(small).find("0.1 m ball"), std::string::npos) << describeBirdBody(small);

    BirdType heavy = customBirdType(CustomBirdDef{5000.0, 3.0, 0.47});
    const BirdBody big = birdCollisionBody(heavy, 2.5);
    EXPECT_EQ(big.radiusM, 1.5);
    EXPECT_EQ(big.massKg, 25.0) << "ten times the lightest body";
    EXPECT_NE(describeBirdBody(big).find("25 kg"), std::string::npos) << describeBirdBody(big);
    EXPECT_EQ(birdCollisionBody(heavy, 0.0).massKg, 5000.0) << "nothing to crush: no clamp";
}

TEST(SceneOverrides, ExtremeCustomBirdsFlyAndCollideWithoutBreakingTheWorld)
{
    // PhET Lab's corners: every combination of the smallest and largest mass, diameter and drag coefficient, in
    // thick air with wind, at a tower. The preview covers all of them; the world stays finite and settles.
    for (const double mass : {0.01, 5000.0})
        for (const double diameter : {0.01, 3.0})
            for (const double cd : {0.04, 1.2})
            {
                SCOPED_TRACE(std::to_string(mass) + " kg, " + std::to_string(diameter) + " m, Cd " +
                             std::to_string(cd));
                LevelDef level = scene();
                level.customBird = CustomBirdDef{mass, diameter, cd};
                level.birds = {kCustomBirdName};
                level.slingshot.y = 2.0;
                level.slingshot.maxForceN = 1.0e6;
                level.slingshot.bandMassKg = 0.0;
                level.blocks.push_back({BlockShape::Box, "ice", 20.0, 1.5, 1.0, 1.0, 0.0, 0.1});
                GameSession session(level);
                const double speed = std::min(30.0, session.maxLaunchSpeed());
                const PredictedFlight preview = session.preview(20.0, speed);
                ASSERT_FALSE(preview.path.empty());
                for (const PathPoint& p : preview.path)
                    ASSERT_TRUE(std::isfinite(p.state.position.x) && std::isfinite(p.state.position.y) &&
                                std::isfinite(p.state.velocity.x));
                session.launch(20.0, speed);
                for (int i = 0; i < 60 * 25 && !session.finished(); ++i)
                {
                    session.step();
                    ASSERT_FALSE(session.world().hasNonFiniteState()) << "step " << i;
                }
                EXPECT_TRUE(session.notice().empty()) << session.notice();
                const ShotRecord& shot = session.shots()[0];
                if (shot.predictedContact && shot.deviationM)
                {
                    EXPECT_LT(*shot.deviationM, 0.01);
                }
            }
}

TEST(SceneOverrides, ASandboxSceneWithoutPigsIsPlayedUntilItsBirdsAreUsed)
{
    LevelDef level = scene();
    level.sandbox = true;
    level.pigs.clear();
    level.birds = {"red", "red"};
    GameSession session(level);
    for (int shot = 0; shot < 2; ++shot)
    {
        ASSERT_EQ(session.phase(), Phase::Aiming);
        session.launch(45.0, 15.0);
        while (session.phase() == Phase::Flying)
            session.step();
    }
    EXPECT_EQ(session.phase(), Phase::Lost) << "never won: there was nothing to win";
}

} // namespace
} // namespace abalike
