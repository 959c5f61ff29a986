#include <abalike/level/Campaign.hpp>
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
    ASSERT_EQ(campaign.episodes.size(), 5u);
    ASSERT_EQ(campaign.levels.size(), 25u);
    EXPECT_EQ(campaign.levels.front().level.id, "1-1");
    EXPECT_EQ(campaign.levels.back().level.id, "5-4"); // ordered by the model player: the Moon is the hardest
    EXPECT_EQ(campaign.levels[7].episode, 1u);
    EXPECT_EQ(campaign.levelIds()[12], "3-2");
    EXPECT_EQ(campaign.indexOf("4-2"), 16u);
    EXPECT_FALSE(campaign.indexOf("9-9").has_value());
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
            fromMissing = fromMissing || issue.file.ends_with("missing.json");
        }
        EXPECT_TRUE(fromA);
        EXPECT_TRUE(fromMissing);
    }
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace abalike
