#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <algorithm>
#include <cstdio>
#include <gtest/gtest.h>
#include <string>

namespace abalike
{
namespace
{

struct Outcome
{
    ShotRecord shot;
    std::vector<DestroyedEvent> defeats;
    int pigsLeft = 0;
};

/// One red-bird shot at full pull (30 m/s) into the scene, played for `seconds` under the rules now (break-through,
/// and a breaking block's momentum handed on) or the rules before (the solver's impulse as solved, and a breaking
/// block's momentum deleted with it).
Outcome play(const LevelDef& level, double angleDeg, bool breakThrough, double seconds = 8.0)
{
    WorldSettings settings;
    settings.breakThrough = breakThrough;
    settings.handOnMomentum = breakThrough;
    GameSession session(level, Catalog::builtin(), settings);
    session.launch(angleDeg, 30.0);
    for (int i = 0; i < static_cast<int>(seconds * 60.0) && !session.finished(); ++i)
        session.step();
    return {session.shots().at(0), session.defeats(), session.pigsRemaining()};
}

/// A scene on flat ground with the default slingshot (1800 N at 2 m: the red bird leaves at 30 m/s) at (0, 1.5).
LevelDef scene(const std::string& blocksAndPigs)
{
    return parseLevel(R"({"format": 1, "id": "t", "title": "scene", "ground": {"y": 0.0},
        "slingshot": {"x": 0.0, "y": 1.5}, "birds": ["red", "red"], )" +
                          blocksAndPigs + R"(, "stars": [1, 2, 3]})",
                      "scene.json", Catalog::builtin());
}

/// Three storeys of wood (two 0.25 x 1.5 m posts under a 1 m plank, 5.25 m in all) at x = 20, a small pig on the
/// ground 2.4 m right of it.
LevelDef woodTower()
{
    std::string blocks;
    for (int storey = 0; storey < 3; ++storey)
    {
        char buf[400];
        const double base = 1.75 * storey;
        std::snprintf(buf, sizeof buf,
                      R"({"material": "wood", "x": 19.625, "y": %g, "w": 0.25, "h": 1.5},
                         {"material": "wood", "x": 20.375, "y": %g, "w": 0.25, "h": 1.5},
                         {"material": "wood", "x": 20.0, "y": %g, "w": 1.0, "h": 0.25},)",
                      base + 0.75, base + 0.75, base + 1.625);
        blocks += buf;
    }
    blocks.pop_back();
    return scene(R"("blocks": [)" + blocks + R"(], "pigs": [{"type": "small", "x": 22.9, "y": 0.25}])");
}

const DestroyedEvent* pigDefeat(const Outcome& o)
{
    for (const DestroyedEvent& d : o.defeats)
        if (d.kind == EntityKind::Pig)
            return &d;
    return nullptr;
}

// Measured before break-through (the rule kept under breakThrough = false) and after; docs/world-physics.md
// "Break-through" has the table.

TEST(BreakThrough, AWoodTowerHitNearItsTopFallsOnTheSmallPigBesideIt)
{
    // Aims 13.5-15.5 deg meet the top storey 4.0-4.7 m up (of 5.25 m). The bird breaks the near post (60 N s of its
    // 120) and, with the momentum the post had taken handed on to what it pushed, the top of the tower tips over onto
    // the pig 2.4 m away within 2 s at every one of these aims, under a block of its upper storeys each time (4 of 5
    // before the breaking post yielded to the bird, once under the bird itself). Before (no break-through, the broken
    // post's momentum deleted with it) the pig survived every aim. Which block lands on the pig is chaotic (a
    // millimetre early in the fall moves it by decimetres), so the test asks for a tower block, not a given one.
    const LevelDef tower = woodTower();
    int crushedByTheTower = 0;
    for (double angle = 13.5; angle <= 15.5 + 1e-9; angle += 0.5)
    {
        const Outcome now = play(tower, angle, true);
        ASSERT_TRUE(now.shot.actualContact);
        EXPECT_GT(now.shot.actualContact->y, 3.9) << angle;
        EXPECT_LT(now.shot.actualContact->y, 4.7) << angle;
        const DestroyedEvent* pig = pigDefeat(now);
        ASSERT_NE(pig, nullptr) << angle;
        EXPECT_LT(pig->timeS, 2.0) << angle;
        if (pig->cause.kind == CauseKind::Block && pig->cause.index >= 3)
            ++crushedByTheTower; // a block of the upper two storeys
        EXPECT_EQ(pigDefeat(play(tower, angle, false)), nullptr) << angle;
    }
    EXPECT_GE(crushedByTheTower, 3);
}

TEST(BreakThrough, AStoneRoofWhosePostIsKnockedOutDropsOnThePigBeneath)
{
    // A 2.6 x 0.4 m stone roof (250 kg) on two 2 m wood posts; a small pig beneath its near end. Every aim that
    // takes out the near post (4.5-6.5 deg, 1.1-1.7 m up) drops the roof on the pig, before and after.
    const LevelDef roof = scene(R"("blocks": [{"material": "wood", "x": 19.0, "y": 1.0, "w": 0.25, "h": 2.0},
        {"material": "wood", "x": 21.0, "y": 1.0, "w": 0.25, "h": 2.0},
        {"material": "stone", "x": 20.0, "y": 2.2, "w": 2.6, "h": 0.4}],
        "pigs": [{"type": "small", "x": 19.5, "y": 0.25}])");
    for (double angle = 4.5; angle <= 6.5 + 1e-9; angle += 0.5)
        for (const bool breakThrough : {true, false})
        {
            const Outcome o = play(roof, angle, breakThrough);
            ASSERT_TRUE(o.shot.impact) << angle;
            EXPECT_EQ(o.shot.impact->bodyIndex, 0) << angle; // the near post
            EXPECT_TRUE(o.shot.impact->broke) << angle;
            const DestroyedEvent* pig = pigDefeat(o);
            ASSERT_NE(pig, nullptr) << angle;
            EXPECT_EQ(pig->cause.kind, CauseKind::Block) << angle;
            EXPECT_EQ(pig->cause.index, 2) << angle; // the roof
        }
}

TEST(BreakThrough, ARedBirdPassesThroughAnIceBlockToThePigBehindIt)
{
    // A 1 m ice cube (40 kg, 25 N s) with a small pig 1.5 m behind it. The bird breaks the ice, keeps
    // 120 - 25 = 95 N s of its momentum and defeats the pig itself; before, the ice stopped it and the pig lived.
    const LevelDef ice = scene(R"("blocks": [{"material": "ice", "x": 20.0, "y": 0.5, "w": 1.0, "h": 1.0}],
        "pigs": [{"type": "small", "x": 21.5, "y": 0.25}])");
    for (double angle = 2.5; angle <= 4.0 + 1e-9; angle += 0.5)
    {
        const Outcome now = play(ice, angle, true);
        ASSERT_TRUE(now.shot.impact) << angle;
        const FirstImpact& hit = *now.shot.impact;
        EXPECT_TRUE(hit.broke) << angle;
        EXPECT_DOUBLE_EQ(hit.strengthBeforeNs, 25.0);
        // The bird lost only the ice's strength along the normal: v_after = v_before - H / m n.
        const double m = hit.birdMassKg;
        EXPECT_NEAR(hit.birdAfter.vx, hit.birdBefore.vx - 25.0 / m * hit.normal.x, 0.25) << angle;
        EXPECT_GT(hit.birdAfter.vx, 20.0) << angle;
        // The ice absorbed exactly its strength (the ground's friction on it is why bird and block alone do not
        // conserve momentum across this step).
        EXPECT_DOUBLE_EQ(hit.damageNs, 25.0) << angle;
        const DestroyedEvent* pig = pigDefeat(now);
        ASSERT_NE(pig, nullptr) << angle;
        EXPECT_EQ(pig->cause.kind, CauseKind::Bird) << angle;
        EXPECT_EQ(pig->cause.index, -1);
        EXPECT_EQ(pig->shot, 0);

        const Outcome before = play(ice, angle, false);
        ASSERT_TRUE(before.shot.impact) << angle;
        EXPECT_LT(before.shot.impact->birdAfter.vx, 0.5 * hit.birdAfter.vx) << angle;
        EXPECT_EQ(pigDefeat(before), nullptr) << angle;
    }
}

TEST(BreakThrough, ABlockThatHoldsStillStopsTheBird)
{
    // Stone (300 N s) does not break under a red bird (120 N s): nothing is refunded, the bird bounces back.
    const LevelDef wall = scene(R"("blocks": [{"material": "stone", "x": 20.0, "y": 1.0, "w": 1.0, "h": 2.0}],
        "pigs": [{"type": "small", "x": 21.5, "y": 0.25}])");
    const Outcome o = play(wall, 3.5, true, 2.0);
    ASSERT_TRUE(o.shot.impact);
    EXPECT_FALSE(o.shot.impact->broke);
    EXPECT_LT(o.shot.impact->birdAfter.vx, 0.0);
    EXPECT_EQ(pigDefeat(o), nullptr);
}

TEST(Tnt, ACrateHitByTheBirdSetsOffTheNextAndTheBlastsDefeatThePigs)
{
    // Three crates 2.5 m apart (blast radius 3 m): the bird breaks the first (20 N s); its blast gives the second
    // 300 (1 - 2.5 / 3) = 50 N s > 20, and so on down the row. The pigs beside the last crate fall to the blast.
    const LevelDef row = scene(R"("blocks": [{"material": "tnt", "x": 20.0, "y": 0.4, "w": 0.8, "h": 0.8},
        {"material": "tnt", "x": 22.5, "y": 0.4, "w": 0.8, "h": 0.8},
        {"material": "tnt", "x": 25.0, "y": 0.4, "w": 0.8, "h": 0.8},
        {"material": "stone", "x": 31.0, "y": 0.5, "w": 1.0, "h": 1.0}],
        "pigs": [{"type": "small", "x": 26.2, "y": 0.25}, {"type": "medium", "x": 36.0, "y": 0.35}])");
    WorldSettings settings;
    GameSession session(row, Catalog::builtin(), settings);
    session.launch(3.0, 30.0);
    for (int i = 0; i < 180; ++i)
        session.step();
    ASSERT_EQ(session.blasts().size(), 3u);
    EXPECT_EQ(session.blasts()[0].blockIndex, 0);
    EXPECT_EQ(session.blasts()[1].blockIndex, 1);
    EXPECT_EQ(session.blasts()[2].blockIndex, 2);
    EXPECT_DOUBLE_EQ(session.blasts()[0].radiusM, 3.0);
    // The chain runs within the step the bird broke the first crate.
    EXPECT_DOUBLE_EQ(session.blasts()[2].timeS, session.blasts()[0].timeS);
    const std::vector<DestroyedEvent> defeats = session.defeats();
    int crates = 0;
    const DestroyedEvent* nearPig = nullptr;
    for (const DestroyedEvent& d : defeats)
    {
        if (d.kind == EntityKind::Block && d.typeName == "tnt")
        {
            ++crates;
            EXPECT_EQ(d.cause.kind, d.index == 0 ? CauseKind::Bird : CauseKind::Explosion) << d.index;
        }
        if (d.kind == EntityKind::Pig && d.index == 0)
            nearPig = &d;
    }
    EXPECT_EQ(crates, 3);
    ASSERT_NE(nearPig, nullptr);
    EXPECT_EQ(nearPig->cause.kind, CauseKind::Explosion);
    // The far pig, 11 m beyond the last crate behind a stone block, is out of reach.
    EXPECT_EQ(session.pigsRemaining(), 1);
    // The stone block 6 m from the last crate is outside every blast radius and stays whole.
    const auto& entities = session.world().entities();
    const auto stone = std::find_if(entities.begin(), entities.end(),
                                    [](const Entity& e) { return e.kind == EntityKind::Block && e.defIndex == 3; });
    ASSERT_NE(stone, entities.end());
    EXPECT_TRUE(stone->alive);
}

} // namespace
} // namespace abalike
