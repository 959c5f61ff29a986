// The simulate/play timing contract in the window (docs/cli.md): `abalike play --shot` replays what
// `abalike simulate` computes with the same shots -- the same defeats at the same times, score, stars and bodies.
// The headless proof over the whole campaign is SimulatePlayTimingTest; these are the window's own runs of a few.
#include "../SanitizerBuild.hpp"
#include "RunGame.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <string>

namespace abalike::test
{
namespace
{

/// stdout of a shell command.
std::string output(const std::string& command)
{
    std::string out;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr)
        return out;
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
        out.append(buffer, n);
    ::pclose(pipe);
    return out;
}

class ReplayFlow : public ::testing::Test
{
protected:
    ReplayFlow() : m_dir(::testing::UnitTest::GetInstance()->current_test_info()->name())
    {
        std::filesystem::create_directories(m_dir.path() / "data");
    }

    /// Runs the shots both ways on the level and compares what the two runs say.
    void expectSameRun(const std::string& level, const std::string& shots) const
    {
        // The sanitizer build replays one case (AMissThenTheReferenceShotInAWorldStillMoving): the contract's logic
        // is the same in every case, SimulatePlayTimingTest proves it headless there over all of them, and each
        // window run costs several times as much under the sanitizers.
        if (test::kSanitizerBuild && ::testing::UnitTest::GetInstance()->current_test_info()->name() !=
                                         std::string("AMissThenTheReferenceShotInAWorldStillMoving"))
            GTEST_SKIP() << "one window case under the sanitizers";
        const std::string simulated =
            output("'" + std::string(ABALIKE_EXECUTABLE) + "' simulate '" + level + "' " + shots + " --json 2>&1");
        const nlohmann::json expected = nlohmann::json::parse(simulated, nullptr, false);
        ASSERT_FALSE(expected.is_discarded()) << simulated;
        // Frames enough for the whole run: its game time, a half-second hold before each shot, and a margin.
        const int frames = static_cast<int>(std::ceil(expected["sim_time_s"].get<double>() * 60.0)) +
                           30 * expected["birds_used"].get<int>() + 60;
        const GameRun run =
            runGame("play '" + level + "' " + shots + " --frames " + std::to_string(frames) + kWindowSize,
                    m_dir.path() / "data");
        ASSERT_EQ(run.exitCode, 0) << run.err;
        nlohmann::json finished;
        nlohmann::json defeats = nlohmann::json::array();
        for (const nlohmann::json& line : run.trace)
        {
            if (line["event"] == "finished")
                finished = line;
            if (line["event"] == "defeat" && finished.is_null())
                defeats.push_back({{"t", line["t"]}, {"kind", line["kind"]}, {"index", line["index"]}});
        }
        ASSERT_FALSE(finished.is_null()) << "the window did not finish the level in " << frames << " frames";
        nlohmann::json expectedDefeats = nlohmann::json::array();
        for (const nlohmann::json& defeat : expected["defeats"])
            expectedDefeats.push_back({{"t", defeat["t"]}, {"kind", defeat["kind"]}, {"index", defeat["index"]}});
        EXPECT_EQ(defeats, expectedDefeats);
        EXPECT_EQ(finished["won"], expected["won"]);
        EXPECT_EQ(finished["score"], expected["score"]);
        EXPECT_EQ(finished["stars"], expected["stars"]);
        EXPECT_EQ(finished["sim_time_s"], expected["sim_time_s"]);
        EXPECT_EQ(finished["bodies_digest"], expected["bodies_digest"]);
    }

    ScratchDir m_dir;
};

TEST_F(ReplayFlow, TwoShotsWinTheFirstLevelInBoth)
{
    expectSameRun(sourceFile("levels/1-1-first-flight.json"), "--shot 30,18 --shot 5,30");
}

TEST_F(ReplayFlow, AMissThenTheReferenceShotInAWorldStillMoving)
{
    // The first bird brings the tower's top down; the second flies while pieces still settle.
    expectSameRun(sourceFile("levels/1-6-high-and-low.json"), "--shot 30,20 --shot 66.3,16.5");
}

TEST_F(ReplayFlow, TheSolversWinWithAnAbilityOnAGeneratedLevel)
{
    expectSameRun(sourceFile("levels/endless/102-0.3.json"), "--shot 13.8,30 --shot 13.1,30.6,0.64");
}

TEST_F(ReplayFlow, TheSolversThreeShotWinOnAGeneratedLevel)
{
    expectSameRun(sourceFile("tests/level/generated/seed-6.json"), "--shot 35,18 --shot 19.4,20.78 --shot 5,30");
}

TEST_F(ReplayFlow, AnImportedScienceBirdsLevelPlayedToItsEnd)
{
    const std::string level = m_dir.file("imported.json");
    const std::string import = "'" + std::string(ABALIKE_EXECUTABLE) + "' import '" +
                               sourceFile("tests/level/science-birds/generator-frame.xml") + "' -o '" + level +
                               "' 2>&1";
    output(import);
    ASSERT_TRUE(std::filesystem::exists(level)) << output(import);
    expectSameRun(level, "--shot 15,20 --shot 40,18");
}

} // namespace
} // namespace abalike::test
