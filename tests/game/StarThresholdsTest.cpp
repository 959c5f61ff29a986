#include <abalike/design/StarThresholds.hpp>
#include <abalike/level/LevelText.hpp>
#include <algorithm>
#include <gtest/gtest.h>

using namespace abalike;

TEST(StarThresholds, OneForAnyWinTwoForTheMedianThreeForTheEightiethPercentile)
{
    // Ten winning runs: lowest 45512 -> 45500; lower median (5th of 10) 52899 -> 52800; nearest-rank 80th
    // percentile (8th of 10) 58050 -> 58000. The order the runs won in does not matter.
    PlayerDifficulty player;
    player.winScores = {61150, 45512, 52899, 70000, 50000, 53000, 52000, 58050, 47000, 55000};
    EXPECT_EQ(recommendedStars(player, 90000), (std::array<int, 3>{45500, 52800, 58000}));
    // One win: all three at it; all wins equal: the same.
    player.winScores = {30049};
    EXPECT_EQ(recommendedStars(player, 90000), (std::array<int, 3>{30000, 30000, 30000}));
    // Never won by the model player: the solver's score for two and three stars, half of it for one.
    player.winScores.clear();
    EXPECT_EQ(recommendedStars(player, 62180), (std::array<int, 3>{31000, 62100, 62100}));
}

TEST(StarThresholds, HalfTheWinsReachTwoStarsAndAFifthThree)
{
    // Issue 57's curve: 2 stars reached by >= 50 % of the model player's wins, 3 stars by >= 20 %, for any number
    // of wins from 1 to 40 and scores with ties and spread alike.
    for (std::size_t wins = 1; wins <= 40; ++wins)
    {
        for (const int spread : {0, 1, 37, 250, 4999})
        {
            PlayerDifficulty player;
            for (std::size_t run = 0; run < wins; ++run)
                player.winScores.push_back(20000 + static_cast<int>((run * 7919) % wins) * spread);
            const auto stars = recommendedStars(player, 90000);
            const auto reaching = [&](int threshold)
            {
                return static_cast<double>(std::count_if(player.winScores.begin(), player.winScores.end(),
                                                         [&](int score) { return score >= threshold; })) /
                       static_cast<double>(wins);
            };
            EXPECT_GE(reaching(stars[1]), 0.5) << wins << " wins, spread " << spread;
            EXPECT_GE(reaching(stars[2]), 0.2) << wins << " wins, spread " << spread;
            EXPECT_LT(reaching(stars[2]), spread >= 250 && wins >= 5 ? 0.5 : 1.01)
                << wins << " wins, spread " << spread;
        }
    }
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
