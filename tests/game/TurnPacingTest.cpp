#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

LevelDef scene(const std::string& birds, const std::string& blocksAndPigs)
{
    return parseLevel(R"({"format": 1, "id": "t", "title": "pacing", "ground": {"y": 0.0},
        "slingshot": {"x": 0.0, "y": 1.5}, "birds": )" +
                          birds + ", " + blocksAndPigs + R"(, "stars": [1, 2, 3]})",
                      "pacing.json", Catalog::builtin());
}

/// Steps until the phase leaves Flying (or `limitS` passes); returns the world time then.
double stepWhileFlying(GameSession& session, double limitS = 30.0)
{
    while (session.phase() == Phase::Flying && session.simTime() < limitS)
        session.step();
    return session.simTime();
}

/// A stone ball (1 m, 190 kg) on flat ground far from the pig: struck, it rolls on for many seconds (rolling
/// resistance 0.01 barely slows it).
const std::string kBusyScene = R"("blocks": [{"shape": "circle", "material": "stone", "x": 20.0, "y": 0.5, "w": 1.0}],
    "pigs": [{"type": "large", "x": 80.0, "y": 0.5}])";

TEST(TurnPacing, TheNextBirdIsReadyAtTheLatestThreeSecondsAfterFirstContact)
{
    GameSession session(scene(R"(["red", "red", "red"])", kBusyScene));
    session.launch(2.5, 30.0); // into the ball
    const double ready = stepWhileFlying(session);
    ASSERT_EQ(session.phase(), Phase::Aiming);
    const ShotRecord& shot = session.shots().at(0);
    ASSERT_TRUE(shot.contactTimeS);
    ASSERT_TRUE(shot.readyAfterContactS);
    EXPECT_NEAR(*shot.readyAfterContactS, ready - *shot.contactTimeS, 1e-9);
    EXPECT_LE(*shot.readyAfterContactS, GameSession::kReadyAfterContactS + session.world().dt());
    // Contact came about 0.7 s after launch: far sooner than the old rule (everything asleep, or 20 s).
    EXPECT_LT(ready, 4.0);
    EXPECT_EQ(session.world().birdsInPlay(), false); // the bird left with a puff
    bool puff = false;
    for (const DestroyedEvent& e : session.destroyed())
        puff = puff || e.kind == EntityKind::Bird;
    EXPECT_TRUE(puff);
}

TEST(TurnPacing, AShotIntoAMovingWorldClaimsNoDeviationAndAShotIntoACalmOneDoes)
{
    GameSession session(scene(R"(["red", "red", "red"])", kBusyScene));
    session.launch(2.5, 30.0);
    stepWhileFlying(session);
    ASSERT_EQ(session.phase(), Phase::Aiming);
    ASSERT_FALSE(session.world().isCalm()) << "the ball should still be rolling when the next bird is ready";
    session.launch(12.0, 30.0);
    stepWhileFlying(session);
    const ShotRecord& moving = session.shots().at(1);
    EXPECT_TRUE(moving.launchedIntoMovingWorld);
    EXPECT_FALSE(moving.deviationM);
    EXPECT_EQ(moving.accuracyPoints, 0);

    // The first shot went into a level at rest: it keeps its deviation.
    const ShotRecord& calm = session.shots().at(0);
    EXPECT_FALSE(calm.launchedIntoMovingWorld);
    ASSERT_TRUE(calm.deviationM);
    EXPECT_LT(*calm.deviationM, 0.01);
}

TEST(TurnPacing, ABirdOnTheGroundLeavesTwoSecondsAfterItFirstTouchedIt)
{
    // A flat, fast shot skids along empty ground: it is not slow, but leaves 2 s after touching down.
    GameSession session(
        scene(R"(["red", "red"])", R"("blocks": [], "pigs": [{"type": "small", "x": 80.0, "y": 0.25}])"));
    session.launch(-10.0, 15.0);
    std::optional<double> touched;
    std::optional<double> gone;
    while (session.simTime() < 6.0 && !gone)
    {
        session.step();
        if (!touched && session.world().shotContactTime())
            touched = session.world().shotContactTime();
        if (session.world().bird() == nullptr && session.world().projectilesInPlay() == 0)
            gone = session.simTime();
    }
    ASSERT_TRUE(touched);
    ASSERT_TRUE(gone);
    EXPECT_GE(*gone - *touched, 0.2);
    EXPECT_LE(*gone - *touched, 2.0 + 2.0 * session.world().dt());
}

TEST(TurnPacing, TheLevelIsWonWithinOneSecondOfTheLastPig)
{
    // The ice-and-pig scene of the break-through tests: the bird passes the ice and defeats the only pig.
    LevelDef level =
        scene(R"(["red", "red", "red"])", R"("blocks": [{"material": "ice", "x": 20.0, "y": 0.5, "w": 1.0, "h": 1.0}],
        "pigs": [{"type": "small", "x": 21.5, "y": 0.25}])");
    GameSession session(level);
    session.launch(3.0, 30.0);
    double lastPigS = -1.0;
    while (!session.finished() && session.simTime() < 10.0)
    {
        session.step();
        if (lastPigS < 0.0 && session.pigsRemaining() == 0)
        {
            lastPigS = session.simTime();
            EXPECT_TRUE(session.winPending());
            EXPECT_THROW(session.launch(10.0, 20.0), LaunchError);
        }
    }
    ASSERT_EQ(session.phase(), Phase::Won);
    EXPECT_LE(session.simTime() - lastPigS, GameSession::kWinGraceS + session.world().dt());
    EXPECT_EQ(session.score().unusedBirds, 2);
}

TEST(TurnPacing, TheLastBirdLosesOnlyOnceTheWorldIsCalm)
{
    GameSession session(scene(R"(["red"])", kBusyScene));
    session.launch(2.5, 30.0);
    stepWhileFlying(session);
    ASSERT_EQ(session.phase(), Phase::Lost);
    EXPECT_TRUE(session.world().isCalm());
    const ShotRecord& shot = session.shots().at(0);
    ASSERT_TRUE(shot.readyAfterContactS);
    // The ball took longer than 3 s to come to rest: the loss waited for it.
    EXPECT_GT(*shot.readyAfterContactS, GameSession::kReadyAfterContactS);
}

TEST(TurnPacing, SimulateFiresEachShotWhenItsBirdIsReady)
{
    const LevelDef level = scene(R"(["red", "red", "red"])", kBusyScene);
    const auto session = simulateShots(level, {{2.5, 30.0}, {12.0, 30.0}});
    ASSERT_EQ(session->shots().size(), 2u);
    const ShotRecord& first = session->shots()[0];
    ASSERT_TRUE(first.readyAfterContactS);
    EXPECT_LE(*first.readyAfterContactS, GameSession::kReadyAfterContactS + session->world().dt());
    EXPECT_TRUE(session->shots()[1].launchedIntoMovingWorld);
}

} // namespace
} // namespace abalike
