#include "RunAbalike.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <nlohmann/json.hpp>

namespace abalike::test
{
namespace
{

const std::string kFirstLevel = sourcePath("levels/1-1-first-flight.json");

std::string malformed(const std::string& name)
{
    return sourcePath("tests/level/malformed/" + name + ".json");
}

/// A level file of the test's own in the temporary folder, removed when the test is done with it.
class ScratchLevel
{
public:
    explicit ScratchLevel(const std::string& name)
        : m_path(std::filesystem::temp_directory_path() /
                 ("abalike-" + name + "-" + std::to_string(::getpid()) + ".json"))
    {
    }
    ~ScratchLevel() { std::filesystem::remove(m_path); }
    ScratchLevel(const ScratchLevel&) = delete;
    ScratchLevel& operator=(const ScratchLevel&) = delete;

    std::string path() const { return m_path.string(); }
    void write(const std::string& text) const { std::ofstream(m_path) << text; }
    std::string read() const
    {
        std::ifstream in(m_path);
        return std::string(std::istreambuf_iterator<char>(in), {});
    }

private:
    std::filesystem::path m_path;
};

/// The expected lines of a malformed file, with the file named by its full path as the CLI prints it.
std::vector<std::string> expectedLines(const std::string& name)
{
    std::ifstream in(sourcePath("tests/level/malformed/" + name + ".expected"));
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);)
        if (!line.empty())
            out.push_back(malformed(name) + line.substr(line.find(".json") + 5));
    return out;
}

TEST(CheckCli, AGoodLevelPasses)
{
    const RunResult r = runAbalike("check " + kFirstLevel);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.rfind("PASS " + kFirstLevel, 0), 0u) << r.out;
    EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST(CheckCli, FillPrintsATextWithTheLevelsValuesAsTheGameFillsIt)
{
    // lesson-angle: the red bird at full pull leaves at sqrt(2 E / m) = sqrt(760.5 * 2 / 4) = 19.5 m/s; its concept
    // says the best angle from its slingshot is 43.9 degrees.
    const std::string lesson = sourcePath("levels/lessons/lesson-angle.json");
    const RunResult r = runAbalike("check " + lesson + " --fill 'v0 {v_max:red} m/s, best {vacuum_best_angle:red}' " +
                                   "--fill '{2 * g|1}'");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("  fill: v0 19.5 m/s, best 43.9\n  fill: 19.6\n"), std::string::npos) << r.out;
    const RunResult json = runAbalike("check " + lesson + " --json --fill '{g}'");
    EXPECT_EQ(nlohmann::json::parse(json.out)["files"][0]["filled"], nlohmann::json::array({"9.81"})) << json.out;
    // A value that does not fill is a usage error naming the text, where and what.
    const RunResult bad = runAbalike("check " + lesson + " --fill 'best {vacum_best_angle:red}'");
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("--fill \"best {vacum_best_angle:red}\" at character 7"), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find("unknown value \"vacum_best_angle\""), std::string::npos) << bad.err;
}

TEST(CheckCli, SolveRecommendsStarsAndWriteStarsWritesOnlyThem)
{
    // A pig in the open: the solver wins it and the model player too; the file's stars (1, 2, 3) are not what its
    // wins recommend, and --write-stars replaces just those numbers.
    const ScratchLevel level("write-stars");
    level.write(R"({"format": 1, "id": "ws", "title": "Write stars",
  "slingshot": {"x": 0, "y": 1.5}, "birds": ["red", "red"],
  "pigs": [{"type": "small", "x": 14, "y": 0.25}],
  "stars": [1, 2, 3]}
)");
    const std::string file = level.path();
    const RunResult dry = runAbalike("check " + file + " --solve --player-runs 4 --json");
    ASSERT_EQ(dry.exitCode, 0) << dry.err;
    // Difficulty within seconds: the model player's first runs, before the solver (here they are all of them).
    EXPECT_NE(dry.err.find("ws: first estimate (4 of 4 model player runs, "), std::string::npos) << dry.err;
    EXPECT_EQ(dry.err.find("refining"), std::string::npos) << dry.err;
    const nlohmann::json report = nlohmann::json::parse(dry.out)["files"][0];
    ASSERT_TRUE(report["recommended_stars"].is_array()) << dry.out;
    const auto stars = report["recommended_stars"].get<std::vector<int>>();
    EXPECT_GT(stars[0], 3);
    EXPECT_LE(stars[0], stars[1]);
    EXPECT_LE(stars[1], stars[2]);
    EXPECT_FALSE(report["stars_written"].get<bool>());
    EXPECT_NE(level.read().find("\"stars\": [1, 2, 3]"), std::string::npos) << "a plain check writes nothing";

    const RunResult wrote = runAbalike("check " + file + " --solve --player-runs 4 --write-stars");
    ASSERT_EQ(wrote.exitCode, 0) << wrote.err;
    EXPECT_NE(wrote.out.find("written into the file"), std::string::npos) << wrote.out;
    const std::string expected = "\"stars\": [" + std::to_string(stars[0]) + ", " + std::to_string(stars[1]) + ", " +
                                 std::to_string(stars[2]) + "]}";
    EXPECT_NE(level.read().find(expected), std::string::npos) << level.read();
    EXPECT_NE(level.read().find("\"birds\": [\"red\", \"red\"],\n  \"pigs\""), std::string::npos)
        << "every other byte as it was";

    const RunResult alone = runAbalike("check " + file + " --write-stars");
    EXPECT_EQ(alone.exitCode, 2);
    EXPECT_NE(alone.err.find("--write-stars: the stars come from the solver and the model player: add --solve"),
              std::string::npos)
        << alone.err;
}

TEST(CheckCli, WriteStarsKeepsAFormattedFileFormatted)
{
    // The same open pig, written by `abalike fmt`, with a reference shot and without stars: fmt puts "stars" before
    // "reference_shot", so --write-stars must not append it at the end; `fmt --check` still passes after it.
    const ScratchLevel level("write-stars-fmt");
    level.write(R"({"format": 1, "id": "wsf", "title": "Write stars",
  "slingshot": {"x": 0, "y": 1.5}, "birds": ["red", "red"],
  "pigs": [{"type": "small", "x": 14, "y": 0.25}], "reference_shot": [45, 12]}
)");
    ASSERT_EQ(runAbalike("fmt " + level.path()).exitCode, 0);
    ASSERT_EQ(level.read().find("\"stars\""), std::string::npos);
    const RunResult wrote = runAbalike("check " + level.path() + " --solve --player-runs 4 --write-stars");
    ASSERT_EQ(wrote.exitCode, 0) << wrote.err;
    EXPECT_NE(level.read().find("\"stars\": ["), std::string::npos) << level.read();
    const RunResult formatted = runAbalike("fmt --check " + level.path());
    EXPECT_EQ(formatted.exitCode, 0) << formatted.out << formatted.err << level.read();
}

TEST(CheckCli, WallsAndMixedTowersPass)
{
    // Bricks side by side, and a tower whose columns change material storey by storey (issue 9).
    const std::string wall = sourcePath("levels/structures/wall-10x20.json");
    const std::string tower = sourcePath("levels/structures/tower-8-mixed.json");
    const RunResult r = runAbalike("check " + wall + " " + tower);
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("PASS " + wall), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("PASS " + tower), std::string::npos) << r.out;
}

class CheckCliMalformed : public ::testing::TestWithParam<std::string>
{
};

/// A few of the malformed suite, through the real executable: FAIL on stdout, every error on stderr, exit 2.
TEST_P(CheckCliMalformed, FailsWithEveryExpectedLine)
{
    const RunResult r = runAbalike("check " + malformed(GetParam()));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out.rfind("FAIL " + malformed(GetParam()), 0), 0u) << r.out;
    for (const std::string& line : expectedLines(GetParam()))
        EXPECT_NE(r.err.find(line), std::string::npos) << "expected: " << line << "\ngot: " << r.err;
}

INSTANTIATE_TEST_SUITE_P(Files, CheckCliMalformed,
                         ::testing::Values("empty", "binary-garbage", "truncated", "huge-number", "invalid-utf8",
                                           "many-problems", "overlapping-blocks", "pig-out-of-reach"),
                         [](const auto& info)
                         {
                             std::string name = info.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

TEST(CheckCli, AClaimThatDoesNotHoldFailsTheLevelAtTheClaim)
{
    // The old 3-5 hint: "Compensate: more power, a steeper angle." In a 6 m/s headwind the farthest shot is
    // lower than in still air, so its claim is false; the concept's claim holds and is not reported.
    const std::string file = sourcePath("tests/level/claims/headwind-aim-higher.json");
    const RunResult r = runAbalike("check " + file);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out.rfind("FAIL " + file + ": 1 claim(s) of its texts do not hold", 0), 0u) << r.out;
    EXPECT_NE(r.err.find(file + ":13:36: error: /claims/1/holds: does not hold for this level: best_angle:red = "
                                "34.01 is not > calm_best_angle:red = 39.41 (so /hints/1 says something untrue)"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("/claims/0"), std::string::npos) << r.err;
}

TEST(CheckCli, AnOutcomeClaimThatDoesNotHoldFailsAtItsOutcome)
{
    // 2-6's towers: the first, hit high at 16 degrees and 28 m/s, lands on the pig of the second (its claim holds, in
    // at least 7 of the 9 aims around the shot); no aim makes it reach the pig of the last.
    const std::string file = sourcePath("tests/level/claims/tower-onto-the-last.json");
    const RunResult r = runAbalike("check " + file);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find(file + ":19:18: error: /claims/1/outcome: does not hold for this level: a pig at x 28 to 29 m "
                                "falls to a block from x 17.5 to 18.5 m in 0 of the 9 aims around 16\u00B0, 28 m/s "
                                "(the claim needs 5) (so /hints/1 says something untrue)"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("/claims/0"), std::string::npos) << r.err;
}

TEST(CheckCli, OneBadFileFailsTheRunButEveryFileIsReported)
{
    const RunResult r = runAbalike("check " + kFirstLevel + " " + malformed("unknown-bird"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.out.find("PASS " + kFirstLevel), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("FAIL " + malformed("unknown-bird")), std::string::npos) << r.out;
}

TEST(CheckCli, HugeAndDeepFilesFailFast)
{
    const auto folder = std::filesystem::temp_directory_path();
    const auto huge = folder / ("abalike-check-huge-" + std::to_string(::getpid()) + ".json");
    const auto deep = folder / ("abalike-check-deep-" + std::to_string(::getpid()) + ".json");
    {
        std::ofstream out(huge, std::ios::binary);
        const std::string chunk(1 << 20, ' ');
        for (int i = 0; i < 50; ++i)
            out << chunk;
    }
    std::ofstream(deep, std::ios::binary) << std::string(100000, '[') << std::string(100000, ']');
    const RunResult r = runAbalike("check " + huge.string() + " " + deep.string());
    std::filesystem::remove(huge);
    std::filesystem::remove(deep);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find(huge.string() + ":1:1: error: /: file too large"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(deep.string() + ":1:65: error: /: JSON nested too deeply"), std::string::npos) << r.err;
}

TEST(CheckCli, JsonReportHasEveryFileAndError)
{
    const RunResult r = runAbalike("check --json " + kFirstLevel + " " + malformed("many-problems"));
    EXPECT_EQ(r.exitCode, 2);
    const auto report = nlohmann::json::parse(r.out);
    EXPECT_FALSE(report["ok"].get<bool>());
    ASSERT_EQ(report["files"].size(), 2u);
    EXPECT_TRUE(report["files"][0]["ok"].get<bool>());
    EXPECT_TRUE(report["files"][0]["rest"]["ok"].get<bool>());
    EXPECT_FALSE(report["files"][1]["ok"].get<bool>());
    EXPECT_EQ(report["files"][1]["errors"].size(), 4u);
    EXPECT_EQ(report["files"][1]["errors"][0]["pointer"], "/birds/1");
    EXPECT_EQ(report["files"][1]["errors"][0]["line"], 6);
}

TEST(CheckCli, CampaignManifestChecksEveryLevelItLists)
{
    const RunResult r = runAbalike("check --json " + sourcePath("levels/campaign.json"));
    EXPECT_EQ(r.exitCode, 0) << r.out;
    const auto report = nlohmann::json::parse(r.out);
    EXPECT_GE(report["files"].size(), 20u);
    for (const auto& file : report["files"])
        EXPECT_TRUE(file["ok"].get<bool>()) << file.dump();
}

TEST(CheckCli, AnUnstableLevelFailsTheRestTest)
{
    const auto path =
        std::filesystem::temp_directory_path() / ("abalike-check-tip-" + std::to_string(::getpid()) + ".json");
    // A tall plank balanced on a narrow ice corner tips over.
    std::ofstream(path) << R"({"format": 1, "id": "tip", "title": "Tip", "slingshot": {"x": 0, "y": 1.5},
      "birds": ["red"], "pigs": [{"type": "small", "x": 14, "y": 0.25}],
      "blocks": [{"material": "stone", "x": 10, "y": 2.5, "w": 0.3, "h": 5, "angle_deg": 10}]})";
    const RunResult r = runAbalike("check " + path.string());
    std::filesystem::remove(path);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.out.find("does not stand"), std::string::npos) << r.out;
    // Located, in words, with the fix: its lowest corner is at x = 10 - 0.15 cos 10 + 2.5 sin 10 = 10.286 m.
    EXPECT_NE(
        r.err.find(":3:18: error: /blocks/0: leans 10\u00B0 on one corner with its centre of mass 28.6 cm past it, "
                   "so it tips over and breaks before any shot; set angle_deg = 0"),
        std::string::npos)
        << r.err;
}

TEST(CheckCli, HeavyOnLightThatStandsIsAWarningNotAFailure)
{
    const auto path =
        std::filesystem::temp_directory_path() / ("abalike-check-ratio-" + std::to_string(::getpid()) + ".json");
    // A 1 m stone cube (240 kg) on a 0.1 m ice plank (10 kg) on stone posts: 24:1, and it stands.
    std::ofstream(path) << R"({"format": 1, "id": "ratio", "title": "Ratio", "slingshot": {"x": 0, "y": 1.5},
      "birds": ["red"], "pigs": [{"type": "small", "x": 21, "y": 0.25}],
      "blocks": [{"material": "stone", "x": 20, "y": 0.5, "w": 0.25, "h": 1},
                 {"material": "stone", "x": 22, "y": 0.5, "w": 0.25, "h": 1},
                 {"material": "ice", "x": 21, "y": 1.05, "w": 2.5, "h": 0.1},
                 {"material": "stone", "x": 21, "y": 1.6, "w": 1, "h": 1}]})";
    const RunResult r = runAbalike("check --json " + path.string());
    std::filesystem::remove(path);
    EXPECT_EQ(r.exitCode, 0) << r.out;
    const auto doc = nlohmann::json::parse(r.out);
    const auto& file = doc["files"][0];
    EXPECT_TRUE(file["ok"].get<bool>());
    ASSERT_EQ(file["warnings"].size(), 1u);
    EXPECT_NE(file["warnings"][0].get<std::string>().find("mass ratio 24"), std::string::npos) << file["warnings"];
}

TEST(CheckCli, FixWorksInRoundsAndSaysWhatItCouldNotFix)
{
    // Stacked floaters (1 cm, then 3 cm above that): both set down, bottom up, and the level stands. A block on
    // nothing has no fix: --fix says so, and why.
    const ScratchLevel level("check-fix-rounds");
    const auto withBlocks = [](const std::string& blocks)
    {
        return R"({"format": 1, "id": "rounds", "title": "Rounds", "slingshot": {"x": 0, "y": 1.5},
  "birds": ["red"], "pigs": [{"type": "small", "x": 24, "y": 0.25}], "blocks": [)" +
               blocks + "]}\n";
    };
    level.write(withBlocks(R"({"material": "wood", "x": 20, "y": 0.51, "w": 1, "h": 1},
             {"material": "wood", "x": 20, "y": 1.54, "w": 1, "h": 1})"));
    const RunResult stacked = runAbalike("check --fix " + level.path());
    EXPECT_EQ(stacked.exitCode, 0) << stacked.out << stacked.err;
    EXPECT_NE(stacked.out.find("/blocks/0/y: 0.51 -> 0.5"), std::string::npos) << stacked.out;
    EXPECT_NE(stacked.out.find("/blocks/1/y: 1.54 -> 1.5"), std::string::npos) << stacked.out;
    EXPECT_NE(stacked.out.find("PASS "), std::string::npos) << stacked.out;

    level.write(withBlocks(R"({"material": "wood", "x": 20, "y": 3, "w": 1, "h": 1})"));
    const RunResult nothing = runAbalike("check --fix " + level.path());
    EXPECT_EQ(nothing.exitCode, 2);
    EXPECT_NE(nothing.out.find("could not fix " + level.path() + ": /blocks/0: falls: nothing is under it"),
              std::string::npos)
        << nothing.out;
}

TEST(CheckCli, FixLowersAFloatingBodyTogetherWithWhatRestsOnIt)
{
    // A box 10 cm up, a plank 1 cm over it and a pig on the plank: once the box is set down, the plank floats 11 cm
    // with the pig on it. Set alone, the pig would be left in the air (the fix used to be "tried and it still
    // moves"); the plank comes down with its pig, by the same height, and the level stands.
    const ScratchLevel level("fix-carry");
    level.write(R"({"format": 1, "id": "carry", "title": "Carry",
  "slingshot": {"x": 0, "y": 1.5}, "birds": ["red", "red"],
  "blocks": [{"material": "wood", "x": 12, "y": 0.6, "w": 1.0, "h": 1.0},
             {"material": "wood", "x": 12, "y": 1.21, "w": 2.0, "h": 0.2}],
  "pigs": [{"type": "small", "x": 12, "y": 1.56}]}
)");
    const RunResult plain = runAbalike("check " + level.path());
    EXPECT_EQ(plain.exitCode, 2);
    EXPECT_NE(plain.err.find("set y = 1.1 (and the body on it down by the same 11.0 cm)"), std::string::npos)
        << plain.err;
    const RunResult fixed = runAbalike("check --fix " + level.path());
    EXPECT_EQ(fixed.exitCode, 0) << fixed.out << fixed.err;
    EXPECT_NE(fixed.out.find("/pigs/0/y: 1.56 -> 1.45 (carried by /blocks/1)"), std::string::npos) << fixed.out;
    EXPECT_NE(fixed.out.find("/blocks/1/y: 1.21 -> 1.1"), std::string::npos) << fixed.out;
    EXPECT_NE(fixed.out.find("PASS "), std::string::npos) << fixed.out;
}

TEST(CheckCli, FixPushesApartOverlapsOfAnyDepthAndBodiesInTheGround)
{
    // A box sunk 5 cm into the one under it, a box 30 cm into the ground and a 2 m post sunk 1.3 m into the post
    // under it (more than a metre, less than its height): the loader refuses the file for each; --fix pushes them
    // out (the nearest free place, on the millimetre), and the rest test passes what it wrote.
    const ScratchLevel level("fix-overlaps");
    level.write(R"({"format": 1, "id": "deep", "title": "Deep",
  "slingshot": {"x": 0, "y": 1.5}, "birds": ["red"],
  "blocks": [{"material": "wood", "x": 12, "y": 0.5, "w": 1.0, "h": 1.0},
             {"material": "wood", "x": 12, "y": 1.45, "w": 1.0, "h": 1.0},
             {"material": "stone", "x": 16, "y": 0.2, "w": 1.0, "h": 1.0},
             {"material": "wood", "x": 24, "y": 1.0, "w": 0.25, "h": 2.0},
             {"material": "wood", "x": 24, "y": 1.7, "w": 0.25, "h": 2.0}],
  "pigs": [{"type": "small", "x": 20, "y": 0.25}]}
)");
    const RunResult plain = runAbalike("check " + level.path());
    EXPECT_EQ(plain.exitCode, 2);
    const RunResult fixed = runAbalike("check --fix " + level.path());
    EXPECT_EQ(fixed.exitCode, 0) << fixed.out << fixed.err;
    EXPECT_NE(fixed.out.find("/blocks/1/y: 1.45 -> 1.5 (overlapped /blocks/0 by 5.0 cm)"), std::string::npos)
        << fixed.out;
    EXPECT_NE(fixed.out.find("/blocks/2/y: 0.2 -> 0.5 (reached 30.0 cm below the ground)"), std::string::npos)
        << fixed.out;
    EXPECT_NE(fixed.out.find("/blocks/4/y: 1.7 -> 3 (overlapped /blocks/3 by 25.0 cm)"), std::string::npos)
        << fixed.out;
    EXPECT_NE(fixed.out.find("PASS "), std::string::npos) << fixed.out;
}

TEST(CheckCli, FixSnapsFloatingAndOverlappingBodiesAndKeepsTheFilesLayout)
{
    const auto path =
        std::filesystem::temp_directory_path() / ("abalike-check-fix-" + std::to_string(::getpid()) + ".json");
    const std::string before = R"({"format": 1, "id": "fix", "title": "Fix", "slingshot": {"x": 0, "y": 1.5},
  "birds": ["red"],
  "pigs": [{"type": "small", "x": 21,   "y": 0.26}],
  "blocks": [
    {"material": "wood", "x": 20, "y": 0.76,  "w": 0.25, "h": 1.5},
    {"material": "wood", "x": 22, "y": 0.75,  "w": 0.25, "h": 1.5},
    {"material": "wood", "x": 21, "y": 1.628, "w": 2.6,  "h": 0.25},
    {"material": "stone", "x": 30, "y": 0.493, "w": 1,   "h": 1}
  ]}
)";
    std::ofstream(path) << before;
    const RunResult plain = runAbalike("check --json " + path.string());
    EXPECT_EQ(plain.exitCode, 2);
    const auto errors = nlohmann::json::parse(plain.out)["files"][0]["errors"];
    ASSERT_GE(errors.size(), 3u);
    EXPECT_EQ(errors[0]["pointer"], "/blocks/0");
    EXPECT_EQ(errors[0]["line"], 5);
    EXPECT_EQ(errors[0]["message"], "floats 1.0 cm above the ground; set y = 0.75");

    const RunResult fixed = runAbalike("check --fix " + path.string());
    std::ifstream in(path);
    const std::string after{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::filesystem::remove(path);
    EXPECT_EQ(fixed.exitCode, 0) << fixed.out << fixed.err;
    EXPECT_NE(fixed.out.find("fixed "), std::string::npos);
    EXPECT_NE(fixed.out.find("/blocks/2/y: 1.628 -> 1.625"), std::string::npos) << fixed.out;
    std::string expected = before;
    for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{{"\"y\": 0.26", "\"y\": 0.25"},
                                                                                   {"\"y\": 0.76,", "\"y\": 0.75,"},
                                                                                   {"\"y\": 1.628", "\"y\": 1.625"},
                                                                                   {"\"y\": 0.493", "\"y\": 0.5"}})
        expected.replace(expected.find(from), from.size(), to);
    EXPECT_EQ(after, expected) << "only the four numbers change, every space and line stays";
}

} // namespace
} // namespace abalike::test

namespace abalike::test
{
namespace
{

TEST(CheckCli, APackLevelWithoutEpisodeIsALocatedErrorWithItsFixAndPlayRefusesThePack)
{
    // A designer's pack: the level copied from the campaign with its "episode" line deleted.
    const std::filesystem::path pack =
        std::filesystem::temp_directory_path() / ("abalike-pack-" + std::to_string(::getpid()));
    std::filesystem::remove_all(pack);
    std::filesystem::create_directories(pack);
    std::ifstream in(sourcePath("levels/1-1-first-flight.json"));
    std::string level{std::istreambuf_iterator<char>(in), {}};
    const std::size_t episode = level.find("  \"episode\"");
    ASSERT_NE(episode, std::string::npos);
    level.erase(episode, level.find('\n', episode) + 1 - episode);
    std::ofstream(pack / "first.json") << level;
    std::ofstream(pack / "campaign.json")
        << R"({"title": "Mine", "episodes": [{"id": "1", "title": "One", "levels": ["first.json"]}]})";
    const std::string file = (pack / "first.json").string();
    const std::string line = file + ":1:1: error: /: has no \"episode\", and the campaign lists it in episode \"1\"; "
                                    "fix: add \"episode\": \"1\"";

    const RunResult check = runAbalike("check " + (pack / "campaign.json").string());
    EXPECT_EQ(check.exitCode, 2);
    EXPECT_NE(check.err.find(line), std::string::npos) << check.err;
    // play --pack says the same lines and opens nothing (no display is needed to refuse).
    const RunResult play = runCommand("env -u DISPLAY " + std::string(ABALIKE_EXECUTABLE) + " play --pack " +
                                      pack.string() + " --frames 1");
    EXPECT_EQ(play.exitCode, 2);
    EXPECT_NE(play.err.find(line), std::string::npos) << play.err;
    EXPECT_NE(play.err.find("does not pass abalike check"), std::string::npos) << play.err;
    std::filesystem::remove_all(pack);
}

} // namespace
} // namespace abalike::test
