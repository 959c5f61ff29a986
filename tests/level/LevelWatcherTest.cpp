#include <abalike/level/LevelWatcher.hpp>
#include <abalike/world/Catalog.hpp>

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

using namespace std::chrono_literals;

const char* const kLevel = R"({"format": 1, "id": "w", "title": "Watched", "slingshot": {"x": 0, "y": 1.5},
  "birds": ["red"], "pigs": [{"type": "small", "x": 10, "y": 0.25}]})";

class LevelWatcherTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        m_path =
            std::filesystem::temp_directory_path() /
            ("abalike-watch-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".json");
        write(kLevel);
    }
    void TearDown() override { std::filesystem::remove(m_path); }

    /// Writes the file and moves its modification time on, as a save a second later would.
    void write(const std::string& text)
    {
        std::ofstream(m_path, std::ios::binary) << text;
        m_time += 1s;
        std::filesystem::last_write_time(m_path, m_time);
    }

    std::filesystem::path m_path;
    std::filesystem::file_time_type m_time = std::filesystem::file_time_type::clock::now();
};

TEST_F(LevelWatcherTest, NothingHappensWhileTheFileIsUnchanged)
{
    LevelWatcher watcher(m_path.string(), Catalog::builtin(), 100ms);
    const auto t0 = LevelWatcher::Clock::now();
    for (int i = 1; i <= 5; ++i)
        EXPECT_FALSE(watcher.poll(t0 + i * 100ms));
}

TEST_F(LevelWatcherTest, ReloadsASavedChangeWithinTwoIntervals)
{
    LevelWatcher watcher(m_path.string(), Catalog::builtin(), 250ms);
    const auto t0 = LevelWatcher::Clock::now();
    std::string edited = kLevel;
    edited.replace(edited.find("Watched"), 7, "Edited!");
    write(edited);
    EXPECT_FALSE(watcher.poll(t0 + 250ms)); // the change is seen, then allowed to settle
    const auto reload = watcher.poll(t0 + 500ms);
    ASSERT_TRUE(reload);
    ASSERT_TRUE(reload->level);
    EXPECT_EQ(reload->level->title, "Edited!");
    EXPECT_FALSE(watcher.poll(t0 + 750ms)); // loaded once, not again
}

TEST_F(LevelWatcherTest, PollsNoMoreOftenThanTheInterval)
{
    LevelWatcher watcher(m_path.string(), Catalog::builtin(), 250ms);
    const auto t0 = LevelWatcher::Clock::now();
    write(std::string(kLevel) + " ");
    EXPECT_FALSE(watcher.poll(t0 + 250ms));
    EXPECT_FALSE(watcher.poll(t0 + 300ms)); // too soon to look again
    EXPECT_TRUE(watcher.poll(t0 + 500ms));
}

TEST_F(LevelWatcherTest, AnInvalidEditReportsEveryProblemAndAFixReloads)
{
    LevelWatcher watcher(m_path.string(), Catalog::builtin(), 100ms);
    const auto t0 = LevelWatcher::Clock::now();
    std::string broken = kLevel;
    broken.replace(broken.find("\"red\""), 5, "\"bleu\"");
    write(broken);
    watcher.poll(t0 + 100ms);
    const auto bad = watcher.poll(t0 + 200ms);
    ASSERT_TRUE(bad);
    EXPECT_FALSE(bad->level);
    ASSERT_EQ(bad->issues.size(), 1u);
    EXPECT_NE(bad->issues[0].format().find("unknown bird \"bleu\" (did you mean \"blue\"?)"), std::string::npos);

    write(kLevel);
    watcher.poll(t0 + 300ms);
    const auto good = watcher.poll(t0 + 400ms);
    ASSERT_TRUE(good);
    EXPECT_TRUE(good->level);
}

TEST_F(LevelWatcherTest, AFileMissingForAMomentIsNotAnError)
{
    LevelWatcher watcher(m_path.string(), Catalog::builtin(), 100ms);
    const auto t0 = LevelWatcher::Clock::now();
    std::filesystem::remove(m_path);
    EXPECT_FALSE(watcher.poll(t0 + 100ms));
    EXPECT_FALSE(watcher.poll(t0 + 200ms));
}

} // namespace
} // namespace abalike
