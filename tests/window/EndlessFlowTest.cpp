// The endless mode driven like a player: from the title or `play --endless`, a shipped castle first, the run's
// loss share up after a win and down after a loss, the results card's choices. Scripted runs take every shipped
// level before a generated one, so their frames never depend on the worker's speed.
#include "RunGame.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace abalike::test
{
namespace
{

class EndlessFlow : public ::testing::Test
{
protected:
    EndlessFlow() : m_dir(::testing::UnitTest::GetInstance()->current_test_info()->name())
    {
        std::filesystem::create_directories(data());
    }
    std::filesystem::path data() const { return m_dir.path() / "data"; }
    std::string script(const std::string& json) const { return " --script '" + m_dir.write("script.json", json) + "'"; }
    GameRun play(const std::string& args) const { return runGame("play " + args + kWindowSize, data()); }

    ScratchDir m_dir;
};

/// The solver's win of the first shipped castle (levels/endless/101-0.3.json, `abalike solve`).
const std::string kWinBridge101 = " --shot 70.0,24.0 --shot 10.0,27.13";

TEST_F(EndlessFlow, TheTitlesEntryOpensAShippedCastleShownByItsSeed)
{
    const GameRun run = play("--frames 20" + script(R"([{"frame": 2, "key": "Down"}, {"frame": 3, "key": "Down"},
        {"frame": 4, "key": "Enter"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("endless-level", "generated"), (std::vector<std::string>{"101:0.3"}));
    EXPECT_EQ(run.values("endless-level", "shipped"), (std::vector<std::string>{"true"}));
    EXPECT_EQ(run.values("level", "title"), (std::vector<std::string>{"Bridge 101"}));
    EXPECT_EQ(run.finalScreens(), (std::vector<std::string>{"title", "play"}));
    const std::vector<std::string> shown = run.values("texts", "shown");
    ASSERT_FALSE(shown.empty());
    EXPECT_NE(shown.back().find("\"Bridge 101\""), std::string::npos) << "the HUD names the castle by its seed alone";
}

TEST_F(EndlessFlow, AWinMakesTheNextCastleHarderAndTheCardCountsTheRun)
{
    const GameRun run = play("--endless --frames 960" + kWinBridge101 + script(R"([{"frame": 920, "key": "N"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("finished", "won"), (std::vector<std::string>{"true"}));
    EXPECT_EQ(run.values("endless-record", "levels_won"), (std::vector<std::string>{"1"}));
    EXPECT_EQ(run.values("endless-record", "ended"), (std::vector<std::string>{"false"}));
    EXPECT_EQ(run.values("endless-record", "longest_run"), (std::vector<std::string>{"1"}));
    const std::vector<std::string> shares = run.values("endless-level", "loss_share");
    ASSERT_EQ(shares.size(), 2u) << "N on the card opens the next castle";
    EXPECT_EQ(shares[0], "0.3");
    EXPECT_EQ(shares[1], "0.4") << "one step harder after a win";
    EXPECT_EQ(run.values("endless-level", "run_levels_won").back(), "1");
    EXPECT_EQ(run.finalScreens(), (std::vector<std::string>{"title", "play"}));
}

TEST_F(EndlessFlow, ALossEndsTheRunAndTheNewOneIsEasierWithNoRetry)
{
    // Five birds straight up: no pig is touched.
    std::string shots;
    for (int i = 0; i < 5; ++i)
        shots += " --shot 89,12";
    const GameRun run = play("--endless --frames 1500" + shots + script(R"([{"frame": 1440, "key": "R"},
        {"frame": 1460, "key": "Enter"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("finished", "won"), (std::vector<std::string>{"false"}));
    EXPECT_EQ(run.values("endless-record", "ended"), (std::vector<std::string>{"true"}));
    EXPECT_TRUE(run.values("restart", "id").empty()) << "a lost castle is not retried inside a run";
    const std::vector<std::string> shares = run.values("endless-level", "loss_share");
    ASSERT_EQ(shares.size(), 2u) << "Enter on the card (New run) opens the next castle";
    EXPECT_EQ(shares[1], "0.2") << "one step easier after a loss";
    EXPECT_EQ(run.values("endless-level", "run_levels_won").back(), "0");
}

TEST_F(EndlessFlow, LeavingACastleUnfinishedEndsTheRunAsALossDoes)
{
    // The pause menu's Level select (fifth), back to the title, and Endless castles (third) again.
    const GameRun run = play("--endless --frames 40" + script(R"([{"frame": 5, "key": "Escape"},
        {"frame": 7, "key": "Down"}, {"frame": 8, "key": "Down"}, {"frame": 9, "key": "Down"},
        {"frame": 10, "key": "Down"}, {"frame": 11, "key": "Enter"}, {"frame": 14, "key": "Escape"},
        {"frame": 17, "key": "Down"}, {"frame": 18, "key": "Down"}, {"frame": 19, "key": "Enter"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("endless-left", "levels_won"), (std::vector<std::string>{"0"}));
    EXPECT_EQ(run.values("endless-record", "ended"), (std::vector<std::string>{"true"}));
    const std::vector<std::string> shares = run.values("endless-level", "loss_share");
    ASSERT_EQ(shares.size(), 2u);
    EXPECT_EQ(shares[1], "0.2") << "one step easier, as after a loss";
    EXPECT_EQ(run.finalScreens(), (std::vector<std::string>{"title", "play"}));
}

TEST_F(EndlessFlow, EndlessTakesNoLevelAndSeedNeedsEndless)
{
    const GameRun withLevel = play("--endless --level 1-1 --frames 2");
    EXPECT_EQ(withLevel.exitCode, 2);
    EXPECT_NE(withLevel.err.find("--endless"), std::string::npos) << withLevel.err;
    const GameRun seedAlone = play("--seed 5 --frames 2");
    EXPECT_EQ(seedAlone.exitCode, 2);
    EXPECT_NE(seedAlone.err.find("--seed"), std::string::npos) << seedAlone.err;
}

} // namespace
} // namespace abalike::test
