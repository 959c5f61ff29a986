#include <abalike/level/LevelIO.hpp>
#include <abalike/world/Catalog.hpp>

#include <algorithm>
#include <filesystem>
#include <gtest/gtest.h>
#include <set>

namespace abalike
{
namespace
{

std::vector<std::string> bundledLevels()
{
    std::vector<std::string> paths;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(ABALIKE_SOURCE_DIR) + "/levels"))
        if (entry.path().extension() == ".json" && entry.path().filename() != "campaign.json")
            paths.push_back(entry.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

class BundledLevel : public ::testing::TestWithParam<std::string>
{
};

TEST_P(BundledLevel, LoadsWithBirdsPigsAndEveryMaterial)
{
    const LevelDef level = loadLevel(GetParam(), Catalog::builtin());
    EXPECT_FALSE(level.id.empty());
    EXPECT_FALSE(level.title.empty());
    EXPECT_FALSE(level.birds.empty());
    EXPECT_FALSE(level.pigs.empty());
    EXPECT_EQ(level.sourcePath, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Levels, BundledLevel, ::testing::ValuesIn(bundledLevels()),
                         [](const ::testing::TestParamInfo<std::string>& info)
                         {
                             std::string name = std::filesystem::path(info.param).stem().string();
                             std::replace_if(
                                 name.begin(), name.end(), [](char c) { return !std::isalnum(c); }, '_');
                             return name;
                         });

TEST(LevelFiles, FirstLevelHasTheSliceContent)
{
    const LevelDef level =
        loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/1-1-first-flight.json", Catalog::builtin());
    EXPECT_EQ(level.id, "1-1");
    EXPECT_GE(level.pigs.size(), 2u);
    EXPECT_EQ(level.birds.size(), 3u);
    std::set<std::string> materials;
    for (const BlockDef& b : level.blocks)
        materials.insert(b.material);
    EXPECT_EQ(materials, (std::set<std::string>{"ice", "stone", "wood"}));
    EXPECT_DOUBLE_EQ(level.slingshot.maxForceN, 1800.0);
}

TEST(LevelFiles, CampaignListsExistingLevels)
{
    const auto paths = loadCampaign(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json");
    ASSERT_FALSE(paths.empty());
    for (const std::string& path : paths)
        EXPECT_TRUE(std::filesystem::exists(path)) << path;
}

TEST(LevelFiles, CampaignHasTwentyLevelsInFourEpisodesWithUniqueIdsAndReferenceShots)
{
    const auto episodes = loadCampaignEpisodes(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json");
    EXPECT_GE(episodes.size(), 4u);
    std::set<std::string> ids;
    std::size_t count = 0;
    for (const CampaignEpisode& episode : episodes)
        for (const std::string& path : episode.levelPaths)
        {
            const LevelDef level = loadLevel(path, Catalog::builtin());
            EXPECT_EQ(level.episode, episode.id) << path;
            EXPECT_TRUE(ids.insert(level.id).second) << "duplicate id " << level.id;
            EXPECT_TRUE(level.referenceShot) << path;
            ++count;
        }
    EXPECT_GE(count, 20u);
}

TEST(LevelFiles, CampaignTeachesEveryWorldAndATimeLimit)
{
    std::set<double> gravities;
    bool timeLimit = false;
    bool wind = false;
    bool gusts = false;
    for (const std::string& path : loadCampaign(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json"))
    {
        const LevelDef level = loadLevel(path, Catalog::builtin());
        gravities.insert(level.environment.gravity);
        timeLimit = timeLimit || level.timeLimitS.has_value();
        wind = wind || level.environment.windX != 0.0;
        gusts = gusts || level.environment.gusts.has_value();
    }
    for (const double g : {9.81, 1.62, 3.71, 24.79})
        EXPECT_EQ(gravities.count(g), 1u) << g;
    EXPECT_TRUE(timeLimit);
    EXPECT_TRUE(wind);
    EXPECT_TRUE(gusts);
}

} // namespace
} // namespace abalike
