#include "TestCatalog.hpp"

#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/world/StressScenes.hpp>
#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

/// Stone that cannot break, so whatever gets past a wall went through it.
const Catalog& unbreakable()
{
    static const Catalog catalog =
        test::catalogWith([](nlohmann::json& root) { test::materialIn(root, "stone")["strength_ns"] = 1e9; });
    return catalog;
}

TEST(LaunchCap, IsOneNumberFromTheCatalogThatTheWorldCanFly)
{
    const Catalog& catalog = Catalog::builtin();
    EXPECT_DOUBLE_EQ(catalog.maxLaunchSpeedMps(), 864.0);
    LevelDef level = towerScene(3);
    level.birds = {"blue"};
    level.slingshot.maxForceN = 1e6; // 1 155 m/s by a massless band alone
    level.slingshot.bandMassKg = 0.0;
    const GameSession session(level, catalog);
    // The world sub-steps so that no body moves more than 90 % of b2_maxTranslation per sub-step: the cap must not
    // ask more of it.
    EXPECT_LE(catalog.maxLaunchSpeedMps(), session.world().maxSpeedMps());
    EXPECT_DOUBLE_EQ(session.maxLaunchSpeed(), catalog.maxLaunchSpeedMps());
    EXPECT_DOUBLE_EQ(maxLaunchSpeed(level, *catalog.findBird("blue"), catalog), catalog.maxLaunchSpeedMps());
    // Below the cap the band decides: v0 = sqrt(F x / (m + m_b)).
    level.slingshot.maxForceN = 1200.0;
    level.slingshot.bandMassKg.reset();
    EXPECT_DOUBLE_EQ(GameSession(level, catalog).maxLaunchSpeed(), std::sqrt(1200.0 * 2.0 / (1.5 + 14.0)));
}

TEST(LaunchCap, EveryBirdAtTheCapLandsWhereThePreviewSaysAndStopsAtTheWall)
{
    // A long, flat flight: 150 m at 864 m/s takes 10 steps of 8 sub-steps each.
    for (const BirdType& bird : unbreakable().birds())
        for (const bool dynamicWall : {false, true})
        {
            LevelDef level;
            level.birds = {bird.name};
            level.pigs = {{"small", 170.0, 0.25}};
            level.slingshot.maxForceN = 1e6;
            level.slingshot.bandMassKg = 0.0;
            if (dynamicWall)
                level.blocks.push_back({BlockShape::Box, "stone", 150.0, 1.5, 0.2, 3.0, 0.0});
            else
                level.terrain.push_back({150.0, 1.5, 0.2, 3.0, 0.0, {}});
            GameSession session(level, unbreakable());
            session.launch(0.2, session.maxLaunchSpeed());
            double furthest = 0.0;
            while (session.phase() == Phase::Flying)
            {
                session.step();
                if (session.world().bird() != nullptr)
                    furthest = std::max(furthest, static_cast<double>(session.world().bird()->body->GetPosition().x));
            }
            const ShotRecord& shot = session.shots().back();
            ASSERT_TRUE(shot.deviationM.has_value()) << bird.name;
            EXPECT_LT(*shot.deviationM, 1e-4) << bird.name << (dynamicWall ? " dynamic" : " static");
            EXPECT_LT(furthest, 150.0) << bird.name << " got through the wall";
        }
}

TEST(LaunchCap, ThePreviewFollowsTheSubStepsOfADeepLevel)
{
    // A 20-row wall is solved in 4 Box2D sub-steps per step, and a contact can begin at any of their boundaries
    // when the skins already overlap there; the preview casts from each of them too. Casting only from whole
    // steps, these two shots were 7.9 and 3.0 mm off.
    WallSpec spec;
    spec.columns = 10;
    spec.rows = 20;
    LevelDef level = wallScene(spec);
    level.birds = {"red"};
    level.slingshot.maxForceN = 1e5;
    for (const auto& [angle, speed] : {std::pair{3.0, 47.0}, std::pair{12.0, 63.0}, std::pair{9.0, 89.0}})
    {
        GameSession session(level);
        ASSERT_EQ(session.world().stackSubsteps(), 4);
        session.step();
        session.launch(angle, speed);
        while (session.phase() == Phase::Flying && !session.shots().back().actualContact)
            session.step();
        const ShotRecord& shot = session.shots().back();
        ASSERT_TRUE(shot.deviationM.has_value()) << angle;
        EXPECT_LT(*shot.deviationM, 1e-4) << angle << " deg, " << speed << " m/s";
    }
}

TEST(LaunchCap, TheLoaderRejectsAReferenceShotAboveIt)
{
    const std::string text = R"({"format": 1, "id": "x", "title": "x", "slingshot": {"x": 0, "y": 1.5,
        "max_force_n": 1000000}, "birds": ["red"], "pigs": [{"x": 20, "y": 0.25}], "reference_shot": [10, 900]})";
    try
    {
        parseLevel(text, "fast.json", Catalog::builtin());
        FAIL() << "a 900 m/s reference shot was accepted";
    }
    catch (const LevelLoadError& e)
    {
        ASSERT_EQ(e.issues().size(), 1u);
        EXPECT_EQ(e.issues()[0].pointer, "/reference_shot/1");
        EXPECT_NE(e.issues()[0].message.find("864"), std::string::npos) << e.issues()[0].message;
    }
}

} // namespace
} // namespace abalike
