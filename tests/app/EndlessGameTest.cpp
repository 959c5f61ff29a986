#include "endless/EndlessGame.hpp"

#include <abalike/level/LevelIO.hpp>
#include <abalike/world/RestCheck.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <set>
#include <thread>
#include <unistd.h>

namespace abalike::app
{
namespace
{

const std::filesystem::path kLevels = std::filesystem::path(ABALIKE_SOURCE_DIR) / "levels";

/// A levels folder of our own: the bundled parts and schema, and the shipped levels we choose.
class EndlessFolder
{
public:
    explicit EndlessFolder(const std::vector<std::string>& shipped)
        : m_root(std::filesystem::temp_directory_path() / ("abalike-endless-" + std::to_string(getpid())))
    {
        std::filesystem::remove_all(m_root);
        std::filesystem::create_directories(m_root / "endless");
        std::filesystem::copy(kLevels / "parts", m_root / "parts");
        std::filesystem::copy(kLevels / "schema", m_root / "schema");
        for (const std::string& name : shipped)
            std::filesystem::copy_file(kLevels / "endless" / name, m_root / "endless" / name);
    }
    ~EndlessFolder() { std::filesystem::remove_all(m_root); }
    const std::filesystem::path& root() const { return m_root; }

private:
    std::filesystem::path m_root;
};

TEST(EndlessGame, TheShippedLevelsLoadStandAndAreNamedBySeedAndLossShare)
{
    const std::vector<EndlessLevel> shipped = loadShippedEndlessLevels(kLevels / "endless");
    ASSERT_GE(shipped.size(), 6u);
    std::set<int> shares;
    std::set<std::string> titles;
    for (const EndlessLevel& level : shipped)
    {
        SCOPED_TRACE(level.generatedName());
        EXPECT_TRUE(level.shipped);
        EXPECT_EQ(level.level.id, "generated-" + std::to_string(level.seed)) << "the file is what generate wrote";
        EXPECT_EQ(level.level.title.substr(level.level.title.rfind(' ') + 1), std::to_string(level.seed))
            << "the title shows the seed that replays it";
        EXPECT_TRUE(checkRest(level.level).passed());
        shares.insert(level.lossShareTenths);
        titles.insert(level.level.title);
    }
    EXPECT_TRUE(shares.count(EndlessRun::kStartTenths)) << "a session's first level is at the run's first share";
    EXPECT_EQ(titles.size(), shipped.size());
    EXPECT_EQ(shipped.front().generatedName(), "101:0.3");
}

TEST(EndlessGame, AShippedLevelNamedOtherwiseIsAnErrorNamingTheFile)
{
    const EndlessFolder folder({});
    std::filesystem::copy_file(kLevels / "endless" / "101-0.3.json", folder.root() / "endless" / "castle.json");
    try
    {
        loadShippedEndlessLevels(folder.root() / "endless");
        FAIL() << "a file not named SEED-L.json loaded";
    }
    catch (const LevelLoadError& error)
    {
        ASSERT_FALSE(error.issues().empty());
        EXPECT_NE(error.issues().front().file.find("castle.json"), std::string::npos);
        EXPECT_NE(error.issues().front().message.find("SEED-L.json"), std::string::npos);
    }
    const EndlessGame game(folder.root(), folder.root() / "cache", 4711, 0);
    EXPECT_NE(game.problem().find("castle.json"), std::string::npos) << game.problem();
}

TEST(EndlessGame, TheFirstLevelIsShippedAtTheRunsShareAndRotatesWithTheRunsPlayed)
{
    const EndlessFolder folder({"101-0.3.json", "102-0.3.json", "104-0.2.json", "105-0.4.json"});
    for (const auto& [runs, expected] : std::vector<std::pair<int, std::uint64_t>>{{0, 101}, {1, 102}, {2, 101}})
    {
        EndlessGame game(folder.root(), folder.root() / "cache", 4711, runs);
        EXPECT_TRUE(game.problem().empty()) << game.problem();
        const std::optional<EndlessLevel> first = game.nextLevel();
        ASSERT_TRUE(first);
        EXPECT_TRUE(first->shipped);
        EXPECT_EQ(first->seed, expected) << runs << " runs played before";
        EXPECT_EQ(first->lossShareTenths, 3);
    }
}

TEST(EndlessGame, WithNothingGeneratedYetTheNearestUnplayedShippedLevelFollows)
{
    const EndlessFolder folder({"101-0.3.json", "104-0.2.json", "105-0.4.json"});
    EndlessGame game(folder.root(), folder.root() / "cache", 4711, 0);
    ASSERT_EQ(game.nextLevel()->seed, 101u);
    game.won(10000);
    EXPECT_EQ(game.run().lossShareTenths(), 4);
    ASSERT_EQ(game.nextLevel()->seed, 105u) << "0.4 after a win";
    const EndlessRun::Result ended = game.lost();
    EXPECT_EQ(ended.levelsWon, 1);
    EXPECT_EQ(ended.score, 10000);
    EXPECT_EQ(game.lastRunEnded().score, 10000);
    EXPECT_EQ(game.run().lossShareTenths(), 3);
    ASSERT_EQ(game.nextLevel()->seed, 104u) << "0.3 played: the nearest left is 0.2";
    // Every shipped level played and (a second after starting) nothing generated yet: wait.
    EXPECT_FALSE(game.nextLevel());
    bool started = false;
    for (int ms = 0; ms < 10000 && !started; ++ms)
    {
        started = game.generation().working || game.generation().generated > 0;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_TRUE(started) << "the worker is generating";
}

} // namespace
} // namespace abalike::app
