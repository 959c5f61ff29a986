#include <abalike/level/Campaign.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/save/Progress.hpp>
#include <abalike/world/Catalog.hpp>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

/// A pack folder NAME with two levels copied from the campaign under new ids and episode "A" (the second without
/// "episode": it belongs to the episode that lists it).
std::filesystem::path makePack(const std::filesystem::path& parent, const std::string& name)
{
    const auto folder = parent / name;
    std::filesystem::create_directories(folder);
    const std::filesystem::path levels = std::filesystem::path(ABALIKE_SOURCE_DIR) / "levels";
    for (const auto& [from, to, id] : {std::tuple{"1-1-first-flight.json", "one.json", "p-1"},
                                       std::tuple{"1-2-the-long-shot.json", "two.json", "p-2"}})
    {
        LevelDef level = loadLevel((levels / from).string(), Catalog::builtin());
        level.id = std::string(id);
        // (std::string(1, 'A'), not "A": GCC 12 warns falsely, -Wrestrict)
        level.episode = std::string(id) == "p-1" ? std::string(1, 'A') : std::string();
        std::ofstream(folder / to) << writeLevelJson(level, "");
    }
    std::ofstream(folder / "campaign.json")
        << R"({"format": 1, "episodes": [{"id": "A", "title": "Warm-up", "levels": ["one.json", "two.json"]}]})";
    return folder;
}

TEST(LevelPack, ItsEpisodesFollowTheCampaignsAndItsProgressKeysNameThePack)
{
    const auto dir = std::filesystem::temp_directory_path() / ("abalike-pack-" + std::to_string(::getpid()));
    const std::filesystem::path manifest = std::filesystem::path(ABALIKE_SOURCE_DIR) / "levels" / "campaign.json";
    Campaign campaign = loadCampaignLevels(manifest.string(), Catalog::builtin());
    const std::size_t bundled = campaign.levels.size();
    appendLevelPack(campaign, makePack(dir, "mypack").string(), Catalog::builtin());
    ASSERT_EQ(campaign.levels.size(), bundled + 2);
    EXPECT_EQ(campaign.levels[bundled].key, "mypack/p-1");
    EXPECT_EQ(campaign.levels[bundled].pack, "mypack");
    EXPECT_EQ(campaign.levels.front().key, "1-1") << "the bundled campaign keeps today's keys";
    EXPECT_EQ(campaign.episodes.back().title, "mypack: Warm-up");
    EXPECT_EQ(campaign.indexOf("mypack/p-2"), bundled + 1);
    EXPECT_EQ(campaign.levels[bundled + 1].level.episode, "A") << "a level without \"episode\" takes its listing's";
    // Numbered by their place in the pack's episode, as every tile is.
    EXPECT_EQ(campaign.levels[bundled + 1].number, "A-2");
    EXPECT_EQ(campaign.indexOfNumber("mypack/A-2"), bundled + 1);
    // The same pack twice is refused (its progress would mix).
    EXPECT_THROW(appendLevelPack(campaign, (dir / "mypack").string(), Catalog::builtin()), LevelLoadError);
    // Installed packs are the folders with a campaign.json.
    std::filesystem::create_directories(dir / "not-a-pack");
    EXPECT_EQ(installedLevelPacks(dir.string()), std::vector<std::string>{(dir / "mypack").string()});
    std::filesystem::remove_all(dir);
}

TEST(LevelPack, APacksFirstLevelIsOpenWhateverTheCampaignsProgress)
{
    Progress progress;
    EXPECT_TRUE(unlockCampaign(progress, {"1-1", "1-2", "mypack/p-1", "mypack/p-2"}));
    EXPECT_TRUE(progress.isUnlocked("1-1"));
    EXPECT_FALSE(progress.isUnlocked("1-2"));
    EXPECT_TRUE(progress.isUnlocked("mypack/p-1"));
    EXPECT_FALSE(progress.isUnlocked("mypack/p-2"));
}

TEST(LevelPack, AFolderWithoutAManifestIsAClearError)
{
    Campaign campaign;
    try
    {
        appendLevelPack(campaign, "/nonexistent/pack", Catalog::builtin());
        ADD_FAILURE();
    }
    catch (const LevelLoadError& e)
    {
        EXPECT_NE(e.issues().front().message.find("a level pack is a folder with a campaign.json"), std::string::npos);
    }
}

} // namespace
} // namespace abalike
