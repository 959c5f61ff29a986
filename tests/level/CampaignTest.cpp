#include <abalike/level/Campaign.hpp>
#include <abalike/save/Progress.hpp>
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
    EXPECT_EQ(campaign.levels.back().level.id, "6-6");
    EXPECT_EQ(campaign.levels[7].episode, 0u);
    EXPECT_EQ(campaign.levels[8].episode, 1u);
    EXPECT_EQ(campaign.levelIds()[16], "3-1");
    EXPECT_EQ(campaign.indexOf("4-2"), 30u); // episode 4 begins at 24: 4-1, 4-4, 4-5, 4-7, 4-6, 4-8, 4-2
    EXPECT_FALSE(campaign.indexOf("9-9").has_value());
}

TEST(Campaign, ALevelsNumberIsItsPlaceAndItsProgressKeyIsItsId)
{
    // The balance orders each episode by difficulty, so the ids no longer count up: the number a player sees (tile,
    // title, play --level) is the level's place in its episode; progress stays under the id, which never moves.
    const Campaign campaign =
        loadCampaignLevels(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json", Catalog::builtin());
    std::size_t place = 0;
    for (std::size_t i = 0; i < campaign.levels.size(); ++i)
    {
        const CampaignLevel& level = campaign.levels[i];
        place = i > 0 && campaign.levels[i - 1].episode == level.episode ? place + 1 : 1;
        EXPECT_EQ(level.number, campaign.episodes[level.episode].id + "-" + std::to_string(place)) << level.level.id;
        EXPECT_EQ(level.key, level.level.id);
        EXPECT_EQ(campaign.indexOfNumber(level.number), i);
    }
    // Episode 2 starts 2-5, 2-4, 2-6: the third tile is 2-6 Boulder Hill, whose id is 2-6; the eighth, numbered
    // 2-8, is Dominoes, saved as 2-1.
    EXPECT_EQ(campaign.levels[*campaign.indexOfNumber("2-3")].key, "2-6");
    const std::size_t dominoes = *campaign.indexOfNumber("2-8");
    EXPECT_EQ(campaign.levels[dominoes].level.title, "Dominoes");
    EXPECT_EQ(campaign.levels[dominoes].key, "2-1");
    EXPECT_FALSE(campaign.indexOfNumber("2-9").has_value());
    EXPECT_EQ(campaign.levelArguments().front(), "1-1");
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
    // A save written by the 25-level campaign: all of episode 1 won, 2-4 won, 2-2 lost, 2-3 unlocked.
    Progress progress = parseProgress(R"({"format": 1,
      "levels": {"1-1": {"best_score": 30000, "stars": 2}, "1-2": {"best_score": 26000, "stars": 3},
                 "1-3": {"best_score": 12000, "stars": 1}, "1-4": {"best_score": 17000, "stars": 3},
                 "1-5": {"best_score": 24000, "stars": 2}, "2-4": {"best_score": 20000, "stars": 1},
                 "2-2": {"best_score": 4000, "stars": 0}},
      "unlocked": ["1-1", "1-2", "1-3", "1-4", "1-5", "2-4", "2-2", "2-3"]})");
    const Progress saved = progress;
    const std::vector<std::string> ids =
        loadCampaignLevels(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json", Catalog::builtin()).levelIds();
    unlockCampaign(progress, ids);

    EXPECT_EQ(progress.levels, saved.levels) << "every star and best score stays";
    // ... with the level it was won on, whatever number that level now shows: 2-4 Rolling Ball is tile 2-2.
    const Campaign campaign =
        loadCampaignLevels(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json", Catalog::builtin());
    EXPECT_EQ(progress.levels.at(campaign.levels[*campaign.indexOfNumber("2-2")].key).bestScore, 20000);
    for (const std::string& id : saved.unlocked)
        EXPECT_TRUE(progress.isUnlocked(id)) << id << " stays open";
    for (std::size_t i = 1; i < ids.size(); ++i)
    {
        const auto previous = progress.levels.find(ids[i - 1]);
        const bool previousWon = previous != progress.levels.end() && previous->second.stars >= 1;
        if (!saved.isUnlocked(ids[i]))
        {
            EXPECT_EQ(progress.isUnlocked(ids[i]), previousWon)
                << ids[i] << " opens exactly when the level before it (" << ids[i - 1] << ") is won";
        }
    }
    std::size_t opened = 0;
    for (const std::string& id : ids)
        opened += progress.isUnlocked(id) ? 1 : 0;
    EXPECT_GT(opened, saved.unlocked.size()) << "new levels after won ones open";
    EXPECT_LT(opened, ids.size()) << "levels after unwon ones stay closed";
}

} // namespace
} // namespace abalike
