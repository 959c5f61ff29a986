#include <abalike/world/GameWorld.hpp>
#include <abalike/world/RestCheck.hpp>
#include <abalike/world/StressScenes.hpp>
#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace abalike
{
namespace
{

/// Touching contacts between two blocks of a wall whose centres differ in both x and y: diagonal neighbours,
/// which meet only corner to corner.
int diagonalContacts(GameWorld& world)
{
    int count = 0;
    for (b2Contact* c = world.box2d().GetContactList(); c != nullptr; c = c->GetNext())
    {
        const b2Body* a = c->GetFixtureA()->GetBody();
        const b2Body* b = c->GetFixtureB()->GetBody();
        if (!c->IsTouching() || a->GetType() != b2_dynamicBody || b->GetType() != b2_dynamicBody)
            continue;
        const b2Vec2 d = a->GetPosition() - b->GetPosition();
        if (std::abs(d.x) > 0.1f && std::abs(d.y) > 0.1f)
            ++count;
    }
    return count;
}

LevelDef tenByTenWall()
{
    WallSpec spec;
    spec.columns = 10;
    spec.rows = 10;
    LevelDef level = wallScene(spec);
    level.pigs = {{"small", 40.0, 0.25}};
    return level;
}

TEST(StructureContacts, DiagonalNeighboursInAWallDoNotTouch)
{
    // Box2D's separating-axis test sees the skins of two corner-to-corner bricks as overlapping (their square
    // skins do, the rounded ones are 21 mm apart); chamfered cores have an axis that separates them.
    GameWorld world(tenByTenWall(), Catalog::builtin());
    world.step();
    EXPECT_EQ(diagonalContacts(world), 0);

    WorldSettings square;
    square.cornerChamferM = 0.0;
    GameWorld without(tenByTenWall(), Catalog::builtin(), square);
    without.step();
    EXPECT_EQ(diagonalContacts(without), 2 * 9 * 9); // every diagonal pair, as before the fix
}

TEST(StructureContacts, ChamferedBricksStillRestExactlyOnTheirDesignedSurfaces)
{
    GameWorld world(tenByTenWall(), Catalog::builtin());
    for (int i = 0; i < 60; ++i)
        world.step();
    for (const Entity& e : world.entities())
        if (e.kind == EntityKind::Block)
        {
            const BlockDef& b = world.level().blocks[static_cast<std::size_t>(e.defIndex)];
            EXPECT_NEAR(e.body->GetPosition().y, b.y, 1e-5) << "block " << e.defIndex;
            EXPECT_NEAR(e.body->GetPosition().x, b.x, 1e-5) << "block " << e.defIndex;
        }
}

/// A row of 0.25 m bricks with a small pig 0.1 m right of the seam between bricks 1 and 2: it rests on brick 2
/// only, 35 mm from the seam, 2.5 mm above the corner of brick 1 (inside Box2D's skin).
LevelDef pigNearASeam()
{
    LevelDef level;
    level.birds = {"red"};
    for (int i = 0; i < 4; ++i)
        level.blocks.push_back({BlockShape::Box, "wood", 20.125 + 0.25 * i, 0.0625, 0.25, 0.125, 0.0});
    level.pigs = {{"small", 20.5 + 0.035, 0.125 + 0.25}};
    return level;
}

int enabledContactsOf(const b2Body* body)
{
    int count = 0;
    for (const b2ContactEdge* e = body->GetContactList(); e != nullptr; e = e->next)
        count += e->contact->IsTouching() && e->contact->IsEnabled() ? 1 : 0;
    return count;
}

TEST(StructureContacts, ABodyDoesNotLeanOnACornerItOnlyApproaches)
{
    GameWorld world(pigNearASeam(), Catalog::builtin());
    world.step();
    const Entity& pig = world.entities().back();
    ASSERT_EQ(pig.kind, EntityKind::Pig);
    EXPECT_EQ(enabledContactsOf(pig.body), 1); // the brick under it only

    WorldSettings plain;
    plain.contactGapM = -1.0; // Box2D's own rule: any skin overlap is a rigid contact
    GameWorld box2d(pigNearASeam(), Catalog::builtin(), plain);
    box2d.step();
    EXPECT_EQ(enabledContactsOf(box2d.entities().back().body), 2); // also the corner of the next brick
}

/// A small pig at rest on the seam between an ice brick and a stone brick lying on the ground.
LevelDef pigOnASeam()
{
    LevelDef level;
    level.birds = {"red"};
    level.blocks = {{BlockShape::Box, "ice", 20.25, 0.125, 0.5, 0.25, 0.0},
                    {BlockShape::Box, "stone", 20.75, 0.125, 0.5, 0.25, 0.0}};
    level.pigs = {{"small", 20.5, 0.5}};
    return level;
}

/// How far the level's last pig got from where it was built after `seconds` (sleep on, as played).
double pigRollM(const LevelDef& level, const WorldSettings& settings, double seconds)
{
    GameWorld world(level, Catalog::builtin(), settings);
    for (int i = 0; i < static_cast<int>(seconds * 60); ++i)
        world.step();
    const Entity& pig = world.entities().back();
    return std::hypot(pig.body->GetPosition().x - level.pigs[0].x, pig.body->GetPosition().y - level.pigs[0].y);
}

TEST(RollingResistance, HoldsAPigOnTheSeamBetweenTwoBlocks)
{
    EXPECT_LT(pigRollM(pigOnASeam(), {}, 10.0), 0.001);
    WorldSettings free;
    free.rollingResistance = false;
    EXPECT_GT(pigRollM(pigOnASeam(), free, 10.0), 0.02); // Box2D alone lets it roll off the seam
}

TEST(RollingResistance, ShortensAKnockedPigsRollButDoesNotStopIt)
{
    // A pig rolling at 2 m/s on flat ground: angular damping and rolling resistance stop it; resistance alone
    // would take about 30 m, so it shortens a knocked pig's roll but does not stop it.
    LevelDef level;
    level.birds = {"red"};
    level.pigs = {{"small", 20.0, 0.25}};
    const auto roll = [&](bool resist)
    {
        WorldSettings settings;
        settings.rollingResistance = resist;
        GameWorld world(level, Catalog::builtin(), settings);
        world.step();
        b2Body* pig = world.entities().back().body;
        pig->SetLinearVelocity(b2Vec2(2.0f, 0.0f));
        pig->SetAngularVelocity(-2.0f / 0.25f);
        for (int i = 0; i < 600; ++i)
            world.step();
        return pig->GetPosition().x - 20.0;
    };
    const double free = roll(false);
    const double resisted = roll(true);
    EXPECT_GT(free, 1.0);
    EXPECT_LT(resisted, free);
    EXPECT_GT(resisted, 0.7 * free); // measured: 5.8 m free, 4.6 m with resistance
}

/// A small pig resting on a 4 m static slope of the given angle.
LevelDef pigOnASlope(double angleDeg)
{
    LevelDef level;
    level.birds = {"red"};
    level.terrain = {{20.0, 1.0, 4.0, 0.5, angleDeg, {}}};
    const double a = angleDeg * std::numbers::pi / 180.0;
    // On the slab's top face, above its centre: 0.25 + 0.25 m along the face normal.
    level.pigs = {{"small", 20.0 - 0.5 * std::sin(a), 1.0 + 0.5 * std::cos(a)}};
    return level;
}

TEST(RollingResistance, HoldsAPigOnlyOnSlopesGentlerThanItsCoefficient)
{
    // Coefficient 0.01: the pig stays on slopes under atan(0.01) = 0.57 degrees and rolls down steeper ones.
    ASSERT_DOUBLE_EQ(Catalog::builtin().rollingResistance(), 0.01);
    EXPECT_LT(pigRollM(pigOnASlope(0.4), {}, 3.0), 0.002);
    EXPECT_GT(pigRollM(pigOnASlope(1.5), {}, 3.0), 0.2);
}

TEST(SettleStep, CountsItsSubStepsForALoadingScreen)
{
    // A 12-block tower settles in 3 sub-steps; a loading screen reads how many are done while the step runs.
    GameWorld world(towerScene(12), Catalog::builtin());
    EXPECT_FALSE(world.settled());
    EXPECT_EQ(world.settleSubstepsPlanned(), 3);
    EXPECT_EQ(world.settleSubstepsDone(), 0);
    world.step();
    EXPECT_TRUE(world.settled());
    EXPECT_EQ(world.settleSubstepsDone(), 3);
    world.step(); // later steps are not settle steps
    EXPECT_EQ(world.settleSubstepsDone(), 3);
}

TEST(StackSubsteps, GrowWithTheDeepestStack)
{
    const auto substeps = [](const LevelDef& level)
    {
        return GameWorld(level, Catalog::builtin()).stackSubsteps();
    };
    EXPECT_EQ(substeps(towerScene(5)), 1);  // depth 5
    EXPECT_EQ(substeps(towerScene(8)), 2);  // depth 8
    EXPECT_EQ(substeps(towerScene(12)), 3); // depth 12
    EXPECT_EQ(substeps(towerScene(20)), 4); // depth 20, the most
    WallSpec tall;
    tall.columns = 20;
    tall.rows = 50;
    EXPECT_EQ(substeps(wallScene(tall)), 4);
    WorldSettings off;
    off.maxStackSubsteps = 1;
    EXPECT_EQ(GameWorld(towerScene(20), Catalog::builtin(), off).stackSubsteps(), 1);
}

TEST(StackSubsteps, EveryStepOfADeepLevelIsSplit)
{
    GameWorld world(towerScene(20), Catalog::builtin());
    for (int i = 0; i < 5; ++i)
    {
        world.step();
        EXPECT_EQ(world.lastSubsteps(), 4);
    }
    EXPECT_EQ(world.substepsFor(0.0), 4);
    EXPECT_EQ(world.substepsFor(500.0), 5); // fast bodies still need their own share of b2_maxTranslation
}

} // namespace
} // namespace abalike
