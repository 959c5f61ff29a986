#include <abalike/save/Progress.hpp>
#include <abalike/save/SaveError.hpp>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

/// The message parseProgress gives for text, or "" when it parses.
std::string progressErrorOf(const std::string& text)
{
    try
    {
        parseProgress(text);
    }
    catch (const SaveFormatError& e)
    {
        return e.what();
    }
    return "";
}

TEST(Progress, RecordKeepsTheBestScoreAndStarsSeparately)
{
    Progress progress;
    EXPECT_TRUE(progress.record("1-1", 20000, 2));
    EXPECT_FALSE(progress.record("1-1", 15000, 1));
    EXPECT_TRUE(progress.record("1-1", 18000, 3));
    EXPECT_EQ(progress.levels.at("1-1"), (LevelRecord{20000, 3}));
    EXPECT_TRUE(progress.record("1-2", 0, 0)) << "a first play is recorded even when it scored nothing";
}

TEST(Progress, RecordClampsWhatTheFileCannotHold)
{
    Progress progress;
    progress.record("1-1", -5, 7);
    EXPECT_EQ(progress.levels.at("1-1"), (LevelRecord{0, 3}));
}

TEST(Progress, CampaignUnlocksTheFirstLevelAndEachOneAfterAWin)
{
    const std::vector<std::string> campaign{"1-1", "1-2", "1-3"};
    Progress progress;
    EXPECT_TRUE(unlockCampaign(progress, campaign));
    EXPECT_EQ(progress.unlocked, (std::set<std::string>{"1-1"}));
    progress.record("1-1", 100, 0); // lost: nothing opens
    EXPECT_FALSE(unlockCampaign(progress, campaign));
    progress.record("1-1", 100, 1);
    EXPECT_TRUE(unlockCampaign(progress, campaign));
    EXPECT_TRUE(progress.isUnlocked("1-2"));
    EXPECT_FALSE(progress.isUnlocked("1-3"));
}

TEST(Progress, ALevelWonByItsFileIsOpenWithTheNextOne)
{
    // Won after `play --level 1-3` while 1-2 was never played: its tile must show its stars, not "locked".
    const std::vector<std::string> campaign = {"1-1", "1-2", "1-3", "1-4", "1-5"};
    Progress progress;
    progress.record("1-3", 5000, 2);
    progress.record("1-5", 100, 0);
    EXPECT_TRUE(unlockCampaign(progress, campaign));
    EXPECT_EQ(progress.unlocked, (std::set<std::string>{"1-1", "1-3", "1-4"}));
}

TEST(Progress, JsonRoundTripsExactly)
{
    Progress progress;
    progress.record("1-1", 31250, 2);
    progress.record("2-4 \"quoted\" / ~", 2147483647, 3);
    progress.unlock("1-1");
    progress.unlock("é");
    const std::string text = progressToJson(progress);
    EXPECT_EQ(parseProgress(text), progress);
    EXPECT_EQ(progressToJson(parseProgress(text)), text) << "saving unchanged progress writes the same bytes";
}

TEST(Progress, WritesOnlyWhatItCanReadBack)
{
    Progress progress;
    progress.levels[""] = {1, 1};
    progress.levels[std::string(300, 'x')] = {1, 1};
    progress.levels["ok"] = {-3, 9};
    progress.unlocked.insert("");
    const Progress back = parseProgress(progressToJson(progress));
    EXPECT_EQ(back.levels.size(), 1u);
    EXPECT_EQ(back.levels.at("ok"), (LevelRecord{0, 3}));
    EXPECT_TRUE(back.unlocked.empty());
}

TEST(Progress, MissingMembersAreEmpty)
{
    EXPECT_EQ(parseProgress(R"({"format": 1})"), Progress{});
    EXPECT_EQ(parseProgress(R"({"format": 2})"), Progress{});
    EXPECT_EQ(parseProgress(R"({"format": 2, "endless": {}})"), Progress{});
}

TEST(Progress, AFormatOneFileKeepsItsStarsAndIsWrittenBackAsFormatThree)
{
    // progress.json as the versions before the endless mode wrote it.
    const Progress old = parseProgress(R"({
  "format": 1,
  "levels": {"1-1": {"best_score": 31250, "stars": 3}, "4-2": {"best_score": 9000, "stars": 1}},
  "unlocked": ["1-1", "1-2", "4-2", "4-3"]
})");
    EXPECT_EQ(old.levels.at("1-1"), (LevelRecord{31250, 3}));
    EXPECT_EQ(old.levels.at("4-2"), (LevelRecord{9000, 1}));
    EXPECT_EQ(old.unlocked, (std::set<std::string>{"1-1", "1-2", "4-2", "4-3"}));
    EXPECT_EQ(old.endless, EndlessRecord{});
    const std::string written = progressToJson(old);
    EXPECT_NE(written.find("\"format\": 3"), std::string::npos) << written;
    EXPECT_NE(written.find("\"endless\""), std::string::npos) << written;
    EXPECT_EQ(parseProgress(written), old);
}

TEST(Progress, EndlessRunsKeepTheBestScoreAndTheLongestRunSeparately)
{
    EndlessRecord record;
    EXPECT_TRUE(record.offer(3, 20000));
    EXPECT_TRUE(record.offer(5, 12000)) << "a longer run is a new best even with fewer points";
    EXPECT_FALSE(record.offer(1, 500)) << "a shorter, poorer run changes no best";
    EXPECT_FALSE(record.offer(-4, -100));
    record.runs = 3;
    EXPECT_EQ(record, (EndlessRecord{20000, 5, 3}));
    Progress progress;
    progress.endless = record;
    EXPECT_EQ(parseProgress(progressToJson(progress)).endless, record);
}

struct BadProgress
{
    const char* name;
    std::string text;
    const char* expected;
};

class ProgressErrors : public ::testing::TestWithParam<BadProgress>
{
};

TEST_P(ProgressErrors, SayWhatIsWrong)
{
    const std::string message = progressErrorOf(GetParam().text);
    EXPECT_NE(message.find(GetParam().expected), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Files, ProgressErrors,
    ::testing::Values(
        BadProgress{"Empty", "", "empty"}, BadProgress{"Blank", " \n\t", "empty"},
        BadProgress{"Truncated", R"({"format": 1, "levels": {"1-1": {"best_sc)", "not valid JSON"},
        BadProgress{"Garbage",
                    std::string("\x7f"
                                "ELF\x02\x01\x01\0\0\0",
                                10),
                    "not valid JSON"},
        BadProgress{"InvalidUtf8", "{\"format\": 1, \"unlocked\": [\"\xff\xfe\"]}", "not valid JSON"},
        BadProgress{"NotAnObject", "[1, 2]", "expected a JSON object, got array"},
        BadProgress{"NoFormat", R"({"levels": {}})", "missing \"format\""},
        BadProgress{"NewerFormat", R"({"format": 4})", "format 4 is not supported (this abalike reads format 1 to 3)"},
        BadProgress{"NumberingAsArray", R"({"format": 3, "numbering": [2]})", "/numbering: expected an object"},
        BadProgress{"NumberingZero", R"({"format": 3, "numbering": {"": 0}})", "/numbering/"},
        BadProgress{"FormatZero", R"({"format": 0})", "format 0 is not supported"},
        BadProgress{"EndlessAsArray", R"({"format": 2, "endless": []})", "/endless: expected an object"},
        BadProgress{"NegativeRun", R"({"format": 2, "endless": {"longest_run": -2}})",
                    "/endless/longest_run: expected a whole number from 0"},
        BadProgress{"RunsAsText", R"({"format": 2, "endless": {"runs": "7"}})",
                    "/endless/runs: expected a whole number"},
        BadProgress{"FormatAsText", R"({"format": "1"})", "/format: expected a whole number"},
        BadProgress{"DeepNesting", std::string(100000, '[') + std::string(100000, ']'), "nests more than"},
        BadProgress{"NaN", R"({"format": 1, "levels": {"1-1": {"best_score": NaN}}})", "not valid JSON"},
        BadProgress{"Infinity", R"({"format": 1, "levels": {"1-1": {"best_score": Infinity}}})", "not valid JSON"},
        BadProgress{"Overflow", R"({"format": 1, "levels": {"1-1": {"best_score": 1e400}}})", "number overflow"},
        BadProgress{"FractionalScore", R"({"format": 1, "levels": {"1-1": {"best_score": 1.5}}})",
                    "/levels/1-1/best_score: expected a whole number from 0 to 2147483647, got 1.5"},
        BadProgress{"HugeScore", R"({"format": 1, "levels": {"1-1": {"best_score": 18446744073709551615}}})",
                    "/levels/1-1/best_score: expected a whole number"},
        BadProgress{"NegativeScore", R"({"format": 1, "levels": {"1-1": {"best_score": -1}}})",
                    "/levels/1-1/best_score"},
        BadProgress{"FourStars", R"({"format": 1, "levels": {"a/b": {"stars": 4}}})",
                    "/levels/a~1b/stars: expected a whole number from 0 to 3, got 4"},
        BadProgress{"LevelsAsArray", R"({"format": 1, "levels": []})", "/levels: expected an object"},
        BadProgress{"EntryAsNumber", R"({"format": 1, "levels": {"1-1": 3}})", "/levels/1-1: expected an object"},
        BadProgress{"EmptyId", R"({"format": 1, "levels": {"": {}}})", "a level id has 1 to 256 characters"},
        BadProgress{"UnlockedNumber", R"({"format": 1, "unlocked": [1]})", "/unlocked/0: expected a string, got 1"},
        BadProgress{"IdTooLong", R"({"format": 1, "unlocked": [")" + std::string(1000, 'x') + "\"]}", "characters"}),
    [](const ::testing::TestParamInfo<BadProgress>& info) { return std::string(info.param.name); });

TEST(Progress, LongValuesAreShortenedInMessages)
{
    const std::string message = progressErrorOf(R"({"format": 1, "unlocked": [[")" + std::string(1000, 'x') + "\"]]}");
    EXPECT_NE(message.find("expected a string"), std::string::npos) << message;
    EXPECT_LT(message.size(), 120u) << message;
}

} // namespace
} // namespace abalike
