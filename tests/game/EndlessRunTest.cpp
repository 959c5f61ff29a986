#include <abalike/game/EndlessRun.hpp>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

TEST(EndlessRun, StartsAtThreeTenthsAndStepsUpAfterAWin)
{
    EndlessRun run;
    EXPECT_EQ(run.lossShareTenths(), 3);
    EXPECT_DOUBLE_EQ(run.lossShare(), 0.3);
    run.won(12000);
    run.won(8000);
    EXPECT_EQ(run.lossShareTenths(), 5);
    EXPECT_EQ(run.levelsWon(), 2);
    EXPECT_EQ(run.score(), 20000);
}

TEST(EndlessRun, ALossEndsTheRunAndTheNextIsOneStepEasier)
{
    EndlessRun run;
    run.won(12000);
    run.won(8000);
    run.won(5000);
    const EndlessRun::Result result = run.lost();
    EXPECT_EQ(result.levelsWon, 3);
    EXPECT_EQ(result.score, 25000);
    EXPECT_EQ(run.lossShareTenths(), 5) << "0.6 after three wins, one step down after the loss";
    EXPECT_EQ(run.levelsWon(), 0);
    EXPECT_EQ(run.score(), 0);
}

TEST(EndlessRun, StaysWhereTheGeneratorFindsLevels)
{
    EndlessRun hard(EndlessRun::kMaxTenths);
    EXPECT_EQ(hard.tenthsAfterWin(), 9);
    hard.won(100);
    EXPECT_EQ(hard.lossShareTenths(), 9);
    EndlessRun easy(0);
    EXPECT_EQ(easy.lossShareTenths(), 1);
    easy.lost();
    EXPECT_EQ(easy.lossShareTenths(), 1);
    EXPECT_EQ(easy.tenthsAfterLoss(), 1);
}

TEST(EndlessRun, ARunScoreNeitherWrapsNorGoesDown)
{
    EndlessRun run;
    run.won(-50);
    EXPECT_EQ(run.score(), 0);
    run.won(2'000'000'000);
    run.won(2'000'000'000);
    EXPECT_EQ(run.score(), 2'147'483'647);
}

} // namespace
} // namespace abalike
