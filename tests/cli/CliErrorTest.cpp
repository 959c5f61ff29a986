#include "RunAbalike.hpp"

#include <algorithm>
#include <gtest/gtest.h>

namespace abalike::test
{
namespace
{

struct BadInvocation
{
    const char* name;
    std::string args;
    const char* expectedInMessage;
};

class CliErrorTest : public ::testing::TestWithParam<BadInvocation>
{
};

/// Bad input: exit code 2, exactly one line on stderr saying what is wrong, nothing on stdout, no crash.
TEST_P(CliErrorTest, ExitsTwoWithOneClearLine)
{
    const BadInvocation& bad = GetParam();
    const RunResult r = runAbalike(bad.args);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(bad.expectedInMessage), std::string::npos) << r.err;
}

const std::string kLevel = sourcePath("levels/1-1-first-flight.json");

INSTANTIATE_TEST_SUITE_P(
    Invocations, CliErrorTest,
    ::testing::Values(
        BadInvocation{"NoSubcommand", "", "subcommand"}, BadInvocation{"UnknownSubcommand", "fly", "fly"},
        BadInvocation{"PredictMissingSpeed", "predict --angle 45 --json", "--speed"},
        BadInvocation{"PredictNotANumber", "predict --angle abc --speed 20 --json", "--angle"},
        BadInvocation{"PredictNaN", "predict --angle 45 --speed nan --json", "--speed"},
        BadInvocation{"PredictInfinite", "predict --angle 45 --speed inf --json", "--speed"},
        BadInvocation{"PredictOverflow", "predict --angle 45 --speed 1e400 --json", "--speed"},
        BadInvocation{"PredictNegativeSpeed", "predict --angle 45 --speed -3 --json", "--speed"},
        BadInvocation{"PredictZeroDt", "predict --angle 45 --speed 20 --dt 0 --json", "--dt"},
        BadInvocation{"PredictNegativeGravity", "predict --angle 45 --speed 20 --gravity -9.81 --json", "gravity"},
        BadInvocation{"PredictTooManySteps", "predict --angle 45 --speed 20 --dt 1e-9 --json", "steps"},
        BadInvocation{"SimulateMissingFile", "simulate /nonexistent/level.json --shot 45,20 --json", "cannot open"},
        BadInvocation{"SimulateDirectory", "simulate /tmp --shot 45,20 --json", "directory"},
        BadInvocation{"SimulateNoShot", "simulate " + kLevel + " --json", "--shot"},
        BadInvocation{"SimulateBadShot", "simulate " + kLevel + " --shot 45 --json", "ANGLE,SPEED"},
        BadInvocation{"SimulateShotAngle", "simulate " + kLevel + " --shot 120,20 --json", "angle"},
        BadInvocation{"SimulateShotNaN", "simulate " + kLevel + " --shot nan,20 --json", "--shot"},
        BadInvocation{"PlayBadSize", "play " + kLevel + " --size 10x10 --frames 1", "--size"},
        BadInvocation{"PlayBadFrames", "play " + kLevel + " --frames -5", "--frames"},
        BadInvocation{"PlayMissingLevel", "play /nonexistent.json --frames 1", "cannot open"},
        BadInvocation{"PlayUnknownLevelId", "play --level 9-9 --frames 1", "no campaign level has the number \"9-9\""},
        BadInvocation{"PlayLevelIdAndFile", "play " + kLevel + " --level 3-2 --frames 1", "--level"}),
    [](const ::testing::TestParamInfo<BadInvocation>& info) { return std::string(info.param.name); });

// The teaching commands: walkthrough and chart range.
INSTANTIATE_TEST_SUITE_P(
    Teaching, CliErrorTest,
    ::testing::Values(
        BadInvocation{"WalkNoVx", "walkthrough --vy 1 --json", "--vx"},
        BadInvocation{"WalkNaNVy", "walkthrough --vx 1 --vy nan --json", "--vy"},
        BadInvocation{"WalkHugeX", "walkthrough --vx 1 --vy 1 --x0 1e400 --json", "--x0"},
        BadInvocation{"WalkZeroDt", "walkthrough --vx 1 --vy 1 --dt 0 --json", "--dt"},
        BadInvocation{"WalkNegativeDt", "walkthrough --vx 1 --vy 1 --dt=-1 --json", "--dt"},
        BadInvocation{"WalkInfT0", "walkthrough --vx 1 --vy 1 --t0 inf --json", "--t0"},
        BadInvocation{"WalkZeroMass", "walkthrough --vx 1 --vy 1 --mass 0 --json", "mass must be > 0"},
        BadInvocation{"WalkNegativeDrag", "walkthrough --vx 1 --vy 1 --quadratic-drag=-1 --json", "quadratic drag"},
        BadInvocation{"WalkBadWind", "walkthrough --vx 1 --vy 1 --wind 3 --json", "--wind"},
        BadInvocation{"WalkOverflow", "walkthrough --vx 1e200 --vy 1e200 --quadratic-drag 1 --json", "overflow"},
        BadInvocation{"WalkStepOverflow", "walkthrough --vx 1e300 --vy 1 --dt 1e10 --json", "overflow"},
        BadInvocation{"WalkUnknownOption", "walkthrough --vx 1 --vy 1 --angle 3 --json", "--angle"},
        BadInvocation{"ChartNoSpeed", "chart range --json", "--speed"},
        BadInvocation{"ChartNoKind", "chart --speed 3", "subcommand"},
        BadInvocation{"ChartNegativeSpeed", "chart range --speed=-3 --json", "--speed"},
        BadInvocation{"ChartBelowGround", "chart range --speed 10 --y0=-1 --json", "--y0"},
        BadInvocation{"ChartFromAboveTo", "chart range --speed 10 --from 50 --to 10 --json", "--from"},
        BadInvocation{"ChartAngleBeyond90", "chart range --speed 10 --to 91 --json", "--from/--to"},
        BadInvocation{"ChartZeroStep", "chart range --speed 10 --step 0 --json", "--step"},
        BadInvocation{"ChartNaNStep", "chart range --speed 10 --step nan --json", "--step"},
        BadInvocation{"ChartTooManyAngles", "chart range --speed 10 --step 1e-6 --json", "more than 100000 angles"},
        BadInvocation{"ChartZeroMaxT", "chart range --speed 10 --max-t 0 --json", "--max-t"},
        BadInvocation{"ChartTooManySteps", "chart range --speed 10 --max-t 1e6 --json", "2 million steps"},
        BadInvocation{"ChartUnwritableOut", "chart range --speed 10 --out /nonexistent/dir/range.png --json",
                      "--out /nonexistent/dir/range.png"},
        BadInvocation{"ChartTooMuchWork", "chart range --speed 10 --step 0.01 --dt 0.001 --json", "100 million steps"},
        BadInvocation{"ChartInfGravity", "chart range --speed 10 --gravity inf --json", "--gravity"},
        BadInvocation{"ChartNegativeGravity", "chart range --speed 10 --gravity=-9.81 --json", "gravity must be >= 0"}),
    [](const ::testing::TestParamInfo<BadInvocation>& info) { return std::string(info.param.name); });

TEST(CliLevelErrors, BrokenLevelReportsFileLineAndColumn)
{
    const std::string path = std::filesystem::temp_directory_path() / "abalike-broken-level.json";
    {
        std::ofstream out(path);
        out << "{\n  \"format\": 1,\n  \"id\": \"x\",\n  \"title\": \"Broken\",\n  \"slingshot\": {\"x\": 0, \"y\": "
               "1.5},\n"
               "  \"birds\": [\"red\"],\n  \"blocks\": [{\"materail\": \"wood\", \"x\": 5, \"y\": 0.5, \"w\": 1, "
               "\"h\": 1}],\n"
               "  \"pigs\": [{\"type\": \"small\", \"x\": 8, \"y\": 0.25}]\n}\n";
    }
    const RunResult r = runAbalike("simulate " + path + " --shot 45,10 --json");
    std::filesystem::remove(path);
    EXPECT_EQ(r.exitCode, 2);
    // Both problems of block 0 are reported, each with its position.
    EXPECT_NE(
        r.err.find(path + ":7:16: error: /blocks/0/materail: unknown key \"materail\" (did you mean \"material\"?)"),
        std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("/blocks/0: missing required key \"material\""), std::string::npos) << r.err;
}

} // namespace
} // namespace abalike::test
