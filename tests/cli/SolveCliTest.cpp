#include "RunAbalike.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace abalike::test
{
namespace
{

/// `abalike simulate LEVEL --shot ...` for the shots of a solve --json answer.
std::string simulateArgs(const std::string& level, const nlohmann::json& shots)
{
    std::string args = "simulate " + level + " --json";
    for (const auto& shot : shots)
    {
        // Appended piece by piece: GCC 12 warns (-Wrestrict) about "literal" + std::string&& here.
        args += " --shot ";
        args += shot["angle_deg"].dump();
        args += ',';
        args += shot["speed"].dump();
        if (!shot["ability_at_s"].is_null())
        {
            args += ',';
            args += shot["ability_at_s"].dump();
        }
    }
    return args;
}

TEST(SolveCli, SolutionReplaysToTheSameScoreWhateverTheThreadCount)
{
    const std::string level = sourcePath("levels/1-6-high-and-low.json");
    // A short model player (3 runs; the default 40 is for measuring, not for tests).
    const RunResult two = runAbalike("solve " + level + " --json --threads 2 --player-runs 3");
    ASSERT_EQ(two.exitCode, 0) << two.err;
    EXPECT_TRUE(two.err.empty()) << "no progress bar when stderr is not a terminal: " << two.err;
    const auto solution = nlohmann::json::parse(two.out);
    for (const char* key : {"level", "won", "score", "stars", "seconds", "shots"})
        EXPECT_TRUE(solution.contains(key)) << key;
    EXPECT_TRUE(solution["won"].get<bool>());
    EXPECT_GE(solution["stars"].get<int>(), 1);
    ASSERT_TRUE(solution.contains("player"));
    for (const char* key : {"runs", "wins", "win_share", "low90", "high90", "win_scores", "simulations", "seconds"})
        EXPECT_TRUE(solution["player"].contains(key)) << key;
    EXPECT_EQ(solution["player"]["runs"], 3);
    // One score per winning run, each a winning score: at least the one-star threshold.
    EXPECT_EQ(solution["player"]["win_scores"].size(), solution["player"]["wins"].get<std::size_t>());
    for (const auto& score : solution["player"]["win_scores"])
        EXPECT_GT(score.get<int>(), 0);
    EXPECT_LE(solution["player"]["low90"].get<double>(), solution["player"]["win_share"].get<double>());

    const RunResult replay = runAbalike(simulateArgs(level, solution["shots"]));
    ASSERT_EQ(replay.exitCode, 0) << replay.err;
    const auto played = nlohmann::json::parse(replay.out);
    EXPECT_EQ(played["score"], solution["score"]);
    EXPECT_EQ(played["won"], solution["won"]);
    EXPECT_EQ(played["stars"], solution["stars"]);

    const RunResult one = runAbalike("solve " + level + " --json --threads 1 --player-runs 0");
    ASSERT_EQ(one.exitCode, 0) << one.err;
    EXPECT_EQ(nlohmann::json::parse(one.out)["shots"], solution["shots"]);
    EXPECT_FALSE(nlohmann::json::parse(one.out).contains("player")) << "--player-runs 0 skips the model player";
}

TEST(SolveCli, BadLevelExitsTwo)
{
    const RunResult r = runAbalike("solve " + sourcePath("tests/level/malformed/unknown-bird.json"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("unknown bird \"bleu\""), std::string::npos) << r.err;
}

} // namespace
} // namespace abalike::test
