#include <abalike/game/GameSession.hpp>

#include <gtest/gtest.h>

namespace abalike
{
namespace
{

LevelDef timedLevel(double limitS)
{
    LevelDef level;
    level.id = "timed";
    level.birds = {"red", "red"};
    level.pigs = {{"small", 20.0, 0.25}};
    level.timeLimitS = limitS;
    return level;
}

TEST(TimeLimit, ClockRunningOutWithPigsStandingLoses)
{
    GameSession session(timedLevel(1.0));
    for (int i = 0; i < 59; ++i) // 59 steps of 1/60 s: 0.983 s, still inside the limit
        session.step();
    EXPECT_EQ(session.phase(), Phase::Aiming);
    session.step(); // 1.0 s
    EXPECT_EQ(session.phase(), Phase::Lost);
    EXPECT_EQ(session.stars(), 0);
}

TEST(TimeLimit, NoLimitMeansNoClock)
{
    LevelDef level = timedLevel(1.0);
    level.timeLimitS.reset();
    GameSession session(level);
    for (int i = 0; i < 600; ++i)
        session.step();
    EXPECT_EQ(session.phase(), Phase::Aiming);
}

} // namespace
} // namespace abalike
