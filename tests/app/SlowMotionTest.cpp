#include "play/SlowMotion.hpp"

#include <gtest/gtest.h>

namespace abalike::app
{
namespace
{

/// Physics steps taken over this many fixed ticks.
int stepsOver(SlowMotion& slow, int ticks)
{
    int steps = 0;
    for (int i = 0; i < ticks; ++i)
        steps += slow.takeStep() ? 1 : 0;
    return steps;
}

TEST(SlowMotion, CyclesRealTimeHalfQuarterAndTakesThatShareOfTheSteps)
{
    SlowMotion slow;
    EXPECT_EQ(slow.divisor(), 1);
    EXPECT_EQ(stepsOver(slow, 120), 120);
    slow.cycle();
    EXPECT_EQ(slow.divisor(), 2);
    EXPECT_EQ(stepsOver(slow, 120), 60);
    slow.cycle();
    EXPECT_EQ(slow.divisor(), 4);
    EXPECT_EQ(stepsOver(slow, 120), 30);
    EXPECT_STREQ(slow.label(), "\u00BC\u00D7");
    slow.cycle();
    EXPECT_EQ(slow.divisor(), 1);
    EXPECT_EQ(stepsOver(slow, 7), 7);
}

} // namespace
} // namespace abalike::app
