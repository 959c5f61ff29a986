#include <abalike/level/Campaign.hpp>
#include <abalike/save/Progress.hpp>
#include <abalike/save/ProgressNumbering.hpp>
#include <abalike/world/Catalog.hpp>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace abalike
{
namespace
{

TEST(Campaign, LoadsEveryLevelInPlayOrder)
{
    const Campaign campaign =
        loadCampaignLevels(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json", Catalog::builtin());
    ASSERT_EQ(campaign.episodes.size(), 6u);
    ASSERT_EQ(campaign.levels.size(), 50u);
    // Ordered by the model player's win rate inside each episode (tools/balance-campaign).
    EXPECT_EQ(campaign.levels.front().level.id, "1-1"); // where the tutorial leads
    EXPECT_EQ(campaign.levels.back().level.id, "6-10");
    EXPECT_EQ(campaign.levels.back().level.title, "Island Fortress");
    EXPECT_EQ(campaign.levels[7].episode, 0u);
    EXPECT_EQ(campaign.levels[8].episode, 1u);
    EXPECT_EQ(campaign.levelIds()[16], "3-1");
    EXPECT_EQ(campaign.indexOf("4-7"), 30u); // episode 4 begins at 24
    EXPECT_FALSE(campaign.indexOf("9-9").has_value());
}

TEST(Campaign, ALevelsIdIsItsNumberItsPlaceAndItsFileName)
{
    // The number a player sees (tile, title, play --level) is the level's place in its episode; its id, the key its
    // progress is saved under, and its file's name say the same (issue 58: the level a student names is the level
    // the teacher opens). The balance reorders episodes; tools/renumber-levels renames what moved.
    const Campaign campaign =
        loadCampaignLevels(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json", Catalog::builtin());
    std::size_t place = 0;
    for (std::size_t i = 0; i < campaign.levels.size(); ++i)
    {
        const CampaignLevel& level = campaign.levels[i];
        place = i > 0 && campaign.levels[i - 1].episode == level.episode ? place + 1 : 1;
        const std::string number = campaign.episodes[level.episode].id + "-" + std::to_string(place);
        EXPECT_EQ(level.number, number) << level.path;
        EXPECT_EQ(level.level.id, number) << level.path << " (run tools/renumber-levels)";
        EXPECT_EQ(level.key, number);
        EXPECT_TRUE(std::filesystem::path(level.path).filename().string().starts_with(number + "-")) << level.path;
        EXPECT_EQ(campaign.indexOfNumber(level.number), i);
    }
    EXPECT_EQ(campaign.levels[*campaign.indexOfNumber("2-3")].level.title, "Boulder Hill");
    EXPECT_EQ(campaign.levels[*campaign.indexOfNumber("2-8")].level.title, "Dominoes");
    EXPECT_FALSE(campaign.indexOfNumber("2-9").has_value());
    EXPECT_EQ(campaign.levelArguments().front(), "1-1");
}

TEST(Campaign, StarsSavedBeforeTheRenumberingStayWithTheirLevels)
{
    // progress.json as the game wrote it before the levels were renumbered (format 2, numbering 1): Dominoes won
    // as 2-1, Pick the Bird as 2-3, Boulder Hill open as 2-6.
    Progress progress = parseProgress(R"({"format": 2,
      "levels": {"2-1": {"best_score": 41000, "stars": 3}, "2-3": {"best_score": 15000, "stars": 1}},
      "unlocked": ["1-1", "2-1", "2-3", "2-6"]})");
    const Campaign campaign =
        loadCampaignLevels(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json", Catalog::builtin());
    ASSERT_TRUE(renumberProgress(progress, campaign));
    const auto recordOf = [&](const std::string& title)
    {
        for (const CampaignLevel& level : campaign.levels)
            if (level.level.title == title)
                return progress.levels.at(level.key);
        return LevelRecord{-1, -1};
    };
    EXPECT_EQ(recordOf("Dominoes"), (LevelRecord{41000, 3}));
    EXPECT_EQ(recordOf("Pick the Bird"), (LevelRecord{15000, 1}));
    EXPECT_EQ(progress.levels.size(), 2u);
    EXPECT_TRUE(progress.isUnlocked(campaign.levels[*campaign.indexOfNumber("2-3")].key)) << "Boulder Hill";
    EXPECT_EQ(progress.numbering.at(""), campaign.numberings.at("").current());
    const Progress once = progress;
    EXPECT_FALSE(renumberProgress(progress, campaign)) << "loading it again renames nothing";
    EXPECT_EQ(progress, once);
}

TEST(Campaign, ReportsTheProblemsOfEveryBrokenLevel)
{
    const auto dir = std::filesystem::temp_directory_path() / ("abalike-campaign-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "campaign.json")
        << R"({"format": 1, "episodes": [{"id": "1", "levels": ["a.json", "b.json", "missing.json"]}]})";
    std::ofstream(dir / "a.json") << R"({"format": 1})";
    std::filesystem::copy_file(std::string(ABALIKE_SOURCE_DIR) + "/levels/1-1-first-flight.json", dir / "b.json",
                               std::filesystem::copy_options::overwrite_existing);
    try
    {
        loadCampaignLevels((dir / "campaign.json").string(), Catalog::builtin());
        FAIL() << "expected errors";
    }
    catch (const LevelLoadError& error)
    {
        bool fromA = false;
        bool fromMissing = false;
        for (const LevelIssue& issue : error.issues())
        {
            fromA = fromA || issue.file.ends_with("a.json");
            // A missing file is the manifest's error, at its entry (not "missing.json:0:0").
            fromMissing =
                fromMissing || (issue.file.ends_with("campaign.json") && issue.pointer == "/episodes/0/levels/2" &&
                                issue.line == 1 && issue.message.find("no level file \"missing.json\"") == 0);
        }
        EXPECT_TRUE(fromA);
        EXPECT_TRUE(fromMissing);
    }
    std::filesystem::remove_all(dir);
}

TEST(Campaign, EveryProblemOfTheManifestAtOnceAtItsOwnLines)
{
    const auto dir = std::filesystem::temp_directory_path() / ("abalike-manifest-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string levels = std::string(ABALIKE_SOURCE_DIR) + "/levels/";
    std::filesystem::copy_file(levels + "1-1-first-flight.json", dir / "a.json",
                               std::filesystem::copy_options::overwrite_existing);
    std::filesystem::copy_file(levels + "1-2-the-long-shot.json", dir / "b.json",
                               std::filesystem::copy_options::overwrite_existing);
    std::filesystem::copy_file(levels + "structures/polygon-hill.json", dir / "sand.json",
                               std::filesystem::copy_options::overwrite_existing);
    std::ofstream(dir / "campaign.json") << R"({"format": 1, "episodes": [
  {"id": "1", "levels": ["a.json", "sand.json", "missing.json", "a.json"]},
  {"id": "2", "levels": ["b.json"]}]})";
    std::vector<std::string> found;
    try
    {
        loadCampaignLevels((dir / "campaign.json").string(), Catalog::builtin());
        ADD_FAILURE() << "a broken manifest loaded";
    }
    catch (const LevelLoadError& error)
    {
        for (const LevelIssue& issue : error.issues())
            found.push_back(std::to_string(issue.line) + ":" + std::to_string(issue.column) + " " + issue.pointer +
                            " " + issue.message.substr(0, 30));
    }
    std::filesystem::remove_all(dir);
    EXPECT_EQ(found, (std::vector<std::string>{
                         "2:36 /episodes/0/levels/1 \"sand.json\" is a sandbox scene",
                         "2:49 /episodes/0/levels/2 no level file \"missing.json\" n",
                         "2:65 /episodes/0/levels/3 \"a.json\" is already listed at ",
                         "3:26 /episodes/1/levels/0 the level says \"episode\": \"1\" ",
                     }));
}

TEST(Campaign, ASaveOfTheFirstTwentyFiveLevelsKeepsItsStarsAndOpensTheNewLevelsInOrder)
{
    // A save written by the 25-level campaign, before the renumbering: all of episode 1 won, 2-4 won, 2-2 lost, 2-3
    // unlocked.
    Progress progress = parseProgress(R"({"format": 1,
      "levels": {"1-1": {"best_score": 30000, "stars": 2}, "1-2": {"best_score": 26000, "stars": 3},
                 "1-3": {"best_score": 12000, "stars": 1}, "1-4": {"best_score": 17000, "stars": 3},
                 "1-5": {"best_score": 24000, "stars": 2}, "2-4": {"best_score": 20000, "stars": 1},
                 "2-2": {"best_score": 4000, "stars": 0}},
      "unlocked": ["1-1", "1-2", "1-3", "1-4", "1-5", "2-4", "2-2", "2-3"]})");
    const Progress saved = progress;
    const Campaign campaign =
        loadCampaignLevels(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json", Catalog::builtin());
    const std::vector<std::string> ids = campaign.levelIds();
    renumberProgress(progress, campaign);
    Progress renamed = saved;
    renumberProgress(renamed, campaign);
    unlockCampaign(progress, ids);

    EXPECT_EQ(progress.levels, renamed.levels) << "every star and best score stays";
    // ... with the level it was won on: 2-4 Rolling Ball is 2-2 since the renumbering.
    EXPECT_EQ(progress.levels.at("2-2").bestScore, 20000);
    for (const std::string& id : renamed.unlocked)
        EXPECT_TRUE(progress.isUnlocked(id)) << id << " stays open";
    for (std::size_t i = 1; i < ids.size(); ++i)
    {
        const auto previous = progress.levels.find(ids[i - 1]);
        const bool previousWon = previous != progress.levels.end() && previous->second.stars >= 1;
        if (!renamed.isUnlocked(ids[i]))
        {
            EXPECT_EQ(progress.isUnlocked(ids[i]), previousWon)
                << ids[i] << " opens exactly when the level before it (" << ids[i - 1] << ") is won";
        }
    }
    std::size_t opened = 0;
    for (const std::string& id : ids)
        opened += progress.isUnlocked(id) ? 1 : 0;
    EXPECT_GT(opened, renamed.unlocked.size()) << "new levels after won ones open";
    EXPECT_LT(opened, ids.size()) << "levels after unwon ones stay closed";
}

} // namespace
} // namespace abalike
