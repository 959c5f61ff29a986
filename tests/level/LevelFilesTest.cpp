#include <abalike/level/LevelIO.hpp>
#include <abalike/world/Catalog.hpp>

#include <algorithm>
#include <filesystem>
#include <gtest/gtest.h>
#include <map>
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
    EXPECT_EQ(level.birds.size(), 4u);
    std::set<std::string> materials;
    for (const BlockDef& b : level.blocks)
        materials.insert(b.material);
    EXPECT_EQ(materials, (std::set<std::string>{"ice", "stone", "wood"}));
    EXPECT_FALSE(level.slingshot.ownsBand()) << "a campaign level uses its world's band";
}

TEST(LevelFiles, CampaignListsExistingLevels)
{
    const auto paths = loadCampaign(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json");
    ASSERT_FALSE(paths.empty());
    for (const std::string& path : paths)
        EXPECT_TRUE(std::filesystem::exists(path)) << path;
}

TEST(LevelFiles, CampaignHasFiftyLevelsInSixEpisodesWithUniqueIdsAndReferenceShots)
{
    const auto episodes = loadCampaignEpisodes(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json");
    EXPECT_GE(episodes.size(), 6u);
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
    EXPECT_GE(count, 50u);
}

TEST(LevelFiles, CampaignIsBuiltLikeTheGenre)
{
    // The countable goals of the campaign (issue 22); the model player's difficulty curve is measured by
    // tools/balance-campaign, a benchmark, not here.
    std::vector<std::size_t> bodiesFromEpisodeTwo;
    std::size_t largest = 0;
    std::size_t levels = 0;
    std::size_t twoShapes = 0;
    std::size_t polygonTerrain = 0;
    std::size_t withTnt = 0;
    std::map<std::string, std::set<std::string>> pigTypesByEpisode;
    for (const CampaignEpisode& episode :
         loadCampaignEpisodes(std::string(ABALIKE_SOURCE_DIR) + "/levels/campaign.json"))
    {
        EXPECT_GE(episode.levelPaths.size(), 8u) << "episode " << episode.id;
        for (const std::string& path : episode.levelPaths)
        {
            const LevelDef level = loadLevel(path, Catalog::builtin());
            ++levels;
            const std::size_t bodies = level.blocks.size() + level.pigs.size();
            largest = std::max(largest, bodies);
            if (episode.id != "1")
                bodiesFromEpisodeTwo.push_back(bodies);
            std::set<BlockShape> shapes;
            for (const BlockDef& block : level.blocks)
                if (block.shape != BlockShape::Box)
                    shapes.insert(block.shape);
            twoShapes += shapes.size() >= 2 ? 1 : 0;
            polygonTerrain += std::any_of(level.terrain.begin(), level.terrain.end(),
                                          [](const TerrainDef& t) { return t.isPolygon(); })
                                  ? 1
                                  : 0;
            withTnt += std::any_of(level.blocks.begin(), level.blocks.end(),
                                   [](const BlockDef& b) { return b.material == "tnt"; })
                           ? 1
                           : 0;
            for (const PigDef& pig : level.pigs)
                pigTypesByEpisode[episode.id].insert(pig.type);
        }
    }
    std::sort(bodiesFromEpisodeTwo.begin(), bodiesFromEpisodeTwo.end());
    ASSERT_FALSE(bodiesFromEpisodeTwo.empty());
    const std::size_t n = bodiesFromEpisodeTwo.size();
    const double median = 0.5 * static_cast<double>(bodiesFromEpisodeTwo[(n - 1) / 2] + bodiesFromEpisodeTwo[n / 2]);
    EXPECT_GE(median, 25.0) << "bodies (blocks and pigs) of the median level from episode 2 on";
    EXPECT_GE(largest, 80u);
    EXPECT_GE(10 * twoShapes, 6 * levels) << twoShapes << " of " << levels << " use two shapes beyond the box";
    EXPECT_GE(polygonTerrain, 12u);
    EXPECT_GE(withTnt, 8u);
    for (const auto& [episode, types] : pigTypesByEpisode)
        if (episode != "1")
        {
            EXPECT_TRUE(types.contains("large")) << "episode " << episode;
            EXPECT_TRUE(types.contains("helmet")) << "episode " << episode;
        }
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
