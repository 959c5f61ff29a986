#include <abalike/design/StarThresholds.hpp>
#include <abalike/level/LevelText.hpp>
#include <gtest/gtest.h>

using namespace abalike;

TEST(StarThresholds, OneForAnyWinTwoForTheMedianThreeForTheNinetiethPercentile)
{
    // Ten winning runs: lowest 45512 -> 45500; lower median (5th of 10) 52899 -> 52800; nearest-rank 90th
    // percentile (9th of 10) 61150 -> 61100. The order the runs won in does not matter.
    PlayerDifficulty player;
    player.winScores = {61150, 45512, 52899, 70000, 50000, 53000, 52000, 58000, 47000, 55000};
    EXPECT_EQ(recommendedStars(player, 90000), (std::array<int, 3>{45500, 52800, 61100}));
    // One win: all three at it; all wins equal: the same.
    player.winScores = {30049};
    EXPECT_EQ(recommendedStars(player, 90000), (std::array<int, 3>{30000, 30000, 30000}));
    // Never won by the model player: the solver's score for two and three stars, half of it for one.
    player.winScores.clear();
    EXPECT_EQ(recommendedStars(player, 62180), (std::array<int, 3>{31000, 62100, 62100}));
}

TEST(StarThresholds, WithStarsRewritesOnlyTheThreeNumbersOrAddsTheKey)
{
    const std::string hand = "{\n  \"id\": \"x\",\n  \"stars\": [ 1,2 ,  3 ],\n  \"birds\": [\"red\"]\n}\n";
    EXPECT_EQ(withStars(hand, {45500, 52800, 61100}),
              "{\n  \"id\": \"x\",\n  \"stars\": [ 45500,52800 ,  61100 ],\n  \"birds\": [\"red\"]\n}\n");
    const std::string none = "{\n  \"id\": \"x\",\n  \"birds\": [\"red\"]\n}\n";
    EXPECT_EQ(withStars(none, {1000, 2000, 3000}),
              "{\n  \"id\": \"x\",\n  \"birds\": [\"red\"],\n  \"stars\": [1000, 2000, 3000]\n}\n");
}
