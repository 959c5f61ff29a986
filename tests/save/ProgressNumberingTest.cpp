#include <abalike/level/LevelIO.hpp>
#include <abalike/level/LevelNumbering.hpp>
#include <abalike/save/ProgressNumbering.hpp>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>

namespace abalike
{
namespace
{

/// Episode 1 of three levels reordered twice: "1-3" moved first (numbering 2), then "1-1" and "1-2" swapped (3).
LevelNumbering twoReorders()
{
    return LevelNumbering{{Renumbering{2, {{"1-3", "1-1"}, {"1-1", "1-2"}, {"1-2", "1-3"}}},
                           Renumbering{3, {{"1-1", "1-2"}, {"1-2", "1-1"}}}}};
}

/// The message loadLevelNumbering gives for a manifest of that text, or "" when it loads.
std::string numberingErrorOf(const std::string& manifest)
{
    const auto path =
        std::filesystem::temp_directory_path() / ("abalike-numbering-" + std::to_string(::getpid()) + ".json");
    std::ofstream(path) << manifest;
    std::string message;
    try
    {
        loadLevelNumbering(path.string());
    }
    catch (const LevelLoadError& error)
    {
        message = error.what();
    }
    std::filesystem::remove(path);
    return message;
}

TEST(LevelNumbering, AnIdFollowsEveryStepAfterTheNumberingItWasSavedUnder)
{
    const LevelNumbering numbering = twoReorders();
    EXPECT_EQ(numbering.current(), 3);
    EXPECT_EQ(numbering.idNow("1-3", 1), "1-2") << "1-3 became 1-1 at numbering 2, then 1-2 at 3";
    EXPECT_EQ(numbering.idNow("1-1", 1), "1-1") << "1-1 became 1-2, then 1-1 again";
    EXPECT_EQ(numbering.idNow("1-2", 1), "1-3");
    EXPECT_EQ(numbering.idNow("1-1", 2), "1-2") << "saved under numbering 2: only the last step applies";
    EXPECT_EQ(numbering.idNow("1-1", 3), "1-1") << "saved under the current numbering: nothing applies";
    EXPECT_EQ(numbering.idNow("2-7", 1), "2-7") << "a level no step names keeps its id";
    EXPECT_EQ(LevelNumbering{}.current(), 1);
}

TEST(LevelNumbering, ProgressOfAnEarlierNumberingKeepsItsStarsOnTheSameLevels)
{
    Progress progress;
    progress.record("1-1", 31000, 3); // the level first called 1-1, now 1-1 again
    progress.record("1-3", 12000, 1); // now 1-2
    progress.record("pack/1-3", 500, 1);
    progress.unlocked = {"1-1", "1-2", "1-3", "pack/1-3"};
    ASSERT_TRUE(renumberProgress(progress, "", twoReorders()));
    EXPECT_EQ(progress.levels.at("1-1"), (LevelRecord{31000, 3}));
    EXPECT_EQ(progress.levels.at("1-2"), (LevelRecord{12000, 1}));
    EXPECT_FALSE(progress.levels.contains("1-3"));
    EXPECT_EQ(progress.levels.at("pack/1-3"), (LevelRecord{500, 1})) << "a pack's keys are not the campaign's";
    EXPECT_EQ(progress.numbering.at(""), 3);
    EXPECT_FALSE(renumberProgress(progress, "", twoReorders())) << "a second load renames nothing";
    EXPECT_EQ(progress.levels.at("1-2"), (LevelRecord{12000, 1}));

    ASSERT_TRUE(renumberProgress(progress, "pack", twoReorders()));
    EXPECT_EQ(progress.levels.at("pack/1-2"), (LevelRecord{500, 1}));
    EXPECT_EQ(progress.unlocked, (std::set<std::string>{"1-1", "1-2", "1-3", "pack/1-2"}));
}

TEST(LevelNumbering, ProgressSavedByALaterCampaignIsLeftAsItIs)
{
    Progress progress;
    progress.record("1-1", 100, 1);
    progress.numbering[""] = 7;
    const Progress before = progress;
    EXPECT_FALSE(renumberProgress(progress, "", twoReorders()));
    EXPECT_EQ(progress, before);
}

TEST(LevelNumbering, TheNumberingOfProgressIsSavedAndReadBack)
{
    Progress progress;
    progress.numbering = {{"", 2}, {"my pack", 1}};
    EXPECT_EQ(parseProgress(progressToJson(progress)), progress);
}

TEST(LevelNumbering, AMalformedHistoryIsLocated)
{
    const std::string episodes = R"("episodes": [{"id": "1", "levels": ["a.json"]}])";
    EXPECT_EQ(numberingErrorOf("{" + episodes + "}"), "");
    EXPECT_NE(numberingErrorOf("{" + episodes + R"(, "renumbered": [{"numbering": 3, "ids": {}}]})")
                  .find("/renumbered/0/numbering: numbering 3 follows numbering 1 (expected 2"),
              std::string::npos);
    EXPECT_NE(
        numberingErrorOf("{" + episodes + R"(, "renumbered": [{"numbering": 2, "ids": {"1-1": "1-2", "1-3": "1-2"}}]})")
            .find("two levels renamed to \"1-2\""),
        std::string::npos);
    EXPECT_NE(numberingErrorOf("{" + episodes + R"(, "renumbered": [{"numbering": 2}]})")
                  .find("missing required key \"ids\""),
              std::string::npos);
    EXPECT_NE(numberingErrorOf("{" + episodes + R"(, "renumbered": [{"numbering": 2, "ids": {"1-1": 4}}]})")
                  .find("/renumbered/0/ids/1-1"),
              std::string::npos);
}

} // namespace
} // namespace abalike
