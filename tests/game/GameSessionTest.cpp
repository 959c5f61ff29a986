#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <box2d/box2d.h>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

LevelDef firstLevel()
{
    return loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/1-1-first-flight.json", Catalog::builtin());
}

TEST(GameSession, LaunchSpeedIsTheBandsEnergyGivenToTheBird)
{
    const GameSession session(firstLevel());
    ASSERT_NE(session.currentBird(), nullptr);
    EXPECT_EQ(session.currentBird()->name, "red");
    // A third of Earth's band: 0.667 m, 2 700 N, 900 J, shared with the band's 14 kg: v0 = sqrt(2 x 900 J / 18 kg)
    // = 10 m/s, and the bird takes 4/18 of it, 200 J.
    EXPECT_DOUBLE_EQ(session.band()->atFraction(1.0 / 3.0).energyJ, 900.0);
    EXPECT_NEAR(session.band()->atFraction(1.0 / 3.0).birdEnergyJ, 200.0, 1e-9);
    EXPECT_NEAR(session.band()->atFraction(1.0 / 3.0).speedMps, 10.0, 1e-12);
    EXPECT_DOUBLE_EQ(session.maxLaunchSpeed(), 30.0);
}

TEST(GameSession, ScriptedShotHitsAndDamages)
{
    const auto session = simulateShots(firstLevel(), {{30.0, 18.0}});
    ASSERT_EQ(session->shots().size(), 1u);
    const ShotRecord& shot = session->shots()[0];
    ASSERT_TRUE(shot.actualContact.has_value());
    ASSERT_TRUE(shot.predictedContact.has_value());
    // It hits the second tower's left column (x = 28 - 0.125) high up, not the ground.
    EXPECT_NEAR(shot.actualContact->x, 27.46, 0.01);
    EXPECT_GT(shot.actualContact->y, 1.0);
    EXPECT_GT(session->score().total(), 0);
    EXPECT_GE(session->score().pigsDefeated + session->score().blocksDestroyed, 1);
    int damaged = 0;
    for (const Entity& e : session->world().entities())
        if ((e.kind == EntityKind::Block || e.kind == EntityKind::Pig) && e.health < e.maxHealth)
            ++damaged;
    EXPECT_GE(damaged, 2);
}

TEST(GameSession, TwoGoodShotsWinTheFirstLevel)
{
    const auto session = simulateShots(firstLevel(), {{55.0, 17.0}, {10.0, 23.0}});
    EXPECT_EQ(session->phase(), Phase::Won);
    EXPECT_EQ(session->pigsRemaining(), 0);
    EXPECT_EQ(session->birdsUsed(), 2);
    EXPECT_EQ(session->score().unusedBirdBonus, 20000); // two reds left
    EXPECT_EQ(session->score().pigsDefeated, 3);
    EXPECT_GE(session->stars(), 1);
}

TEST(GameSession, MissingWithEveryBirdLoses)
{
    const auto session = simulateShots(firstLevel(), {{5.0, 8.0}, {5.0, 8.0}, {5.0, 8.0}, {5.0, 8.0}});
    EXPECT_EQ(session->phase(), Phase::Lost);
    EXPECT_EQ(session->pigsRemaining(), 3);
    EXPECT_EQ(session->stars(), 0);
    EXPECT_EQ(session->score().unusedBirdBonus, 0);
}

TEST(GameSession, SameShotsGiveBitIdenticalResults)
{
    const std::vector<ScriptedShot> shots{{30.0, 18.0}, {45.0, 17.0}};
    const auto a = simulateShots(firstLevel(), shots);
    const auto b = simulateShots(firstLevel(), shots);
    EXPECT_EQ(a->score().total(), b->score().total());
    EXPECT_EQ(a->simTime(), b->simTime());
    ASSERT_EQ(a->shots().size(), b->shots().size());
    for (std::size_t i = 0; i < a->shots().size(); ++i)
        EXPECT_EQ(a->shots()[i].actualPath, b->shots()[i].actualPath);
    for (std::size_t i = 0; i < a->world().entities().size(); ++i)
    {
        const Entity& ea = a->world().entities()[i];
        const Entity& eb = b->world().entities()[i];
        ASSERT_EQ(ea.alive, eb.alive);
        if (ea.body != nullptr)
        {
            EXPECT_EQ(ea.body->GetPosition().x, eb.body->GetPosition().x);
            EXPECT_EQ(ea.body->GetPosition().y, eb.body->GetPosition().y);
        }
    }
}

TEST(GameSession, PreviewEndsAtTheFirstContact)
{
    const GameSession session(firstLevel());
    const PredictedFlight preview = session.preview(35.0, 17.0);
    ASSERT_EQ(preview.end, FlightEnd::Contact);
    ASSERT_TRUE(preview.contact.has_value());
    EXPECT_EQ(preview.path.back().timeS, preview.contact->t);
    EXPECT_EQ(preview.path.back().state.position.x, preview.contact->x);
    // It stops at the left face of the second tower's column (x = 27.875), one bird radius (0.25 m) short.
    EXPECT_NEAR(preview.contact->x, 27.875 - 0.25, 0.015);
    // No earlier point of the path touches anything.
    const double radius = session.currentBird()->radiusM;
    for (std::size_t i = 0; i + 1 < preview.path.size(); ++i)
        EXPECT_FALSE(session.world().castCircle(radius, preview.path[i].state, preview.path[i].state).has_value()) << i;
}

TEST(GameSession, PredictedAndActualFirstContactAgreeWithinOneCentimetre)
{
    for (const ScriptedShot shot : {ScriptedShot{30, 15}, {45, 15}, {35, 17}, {45, 17}, {25, 19}, {50, 18}, {10, 20}})
    {
        const auto session = simulateShots(firstLevel(), {shot});
        const ShotRecord& record = session->shots()[0];
        ASSERT_TRUE(record.deviationM.has_value()) << shot.angleDeg << "," << shot.speedMps;
        EXPECT_LT(*record.deviationM, 0.01) << shot.angleDeg << "," << shot.speedMps;
        EXPECT_NEAR(record.predictedContact->t, record.actualContact->t, 1e-3);
    }
}

TEST(GameSession, LaunchRulesAreEnforced)
{
    GameSession session(firstLevel());
    EXPECT_THROW(session.launch(45.0, 30.5), LaunchError);
    EXPECT_THROW(session.launch(120.0, 10.0), LaunchError);
    session.launch(45.0, 10.0);
    EXPECT_EQ(session.phase(), Phase::Flying);
    EXPECT_THROW(session.launch(45.0, 10.0), LaunchError); // the first shot is still under way
    EXPECT_EQ(session.birdsRemaining(), 3);                // 1-1 has four birds
}

TEST(GameSession, RestartPutsEverythingBack)
{
    GameSession session(firstLevel());
    session.launch(30.0, 18.0);
    while (session.phase() == Phase::Flying)
        session.step();
    ASSERT_GT(session.score().total(), 0);
    session.restart();
    EXPECT_EQ(session.phase(), Phase::Aiming);
    EXPECT_EQ(session.score().total(), 0);
    EXPECT_EQ(session.birdsRemaining(), 4);
    EXPECT_EQ(session.pigsRemaining(), 3);
    EXPECT_TRUE(session.shots().empty());
}

} // namespace
} // namespace abalike
