#include "FileSizeLimit.hpp"
#include "TempDir.hpp"

#include <abalike/save/SaveError.hpp>
#include <abalike/save/SaveStore.hpp>
#include <gtest/gtest.h>
#include <sys/stat.h>

namespace abalike
{
namespace
{

using test::entries;
using test::readText;
using test::TempDir;
using test::writeText;

Progress someProgress()
{
    Progress progress;
    progress.record("1-1", 24000, 2);
    progress.unlock("1-1");
    progress.unlock("1-2");
    return progress;
}

bool anyContains(const std::vector<std::string>& messages, const std::string& part)
{
    for (const std::string& m : messages)
        if (m.find(part) != std::string::npos)
            return true;
    return false;
}

std::string joined(const std::vector<std::string>& messages)
{
    std::string all;
    for (const std::string& m : messages)
        all += m + "\n";
    return all;
}

TEST(SaveStore, NoFilesMeansDefaultsAndNoMessage)
{
    const TempDir dir;
    SaveStore store(dir / "abalike");
    store.load();
    EXPECT_EQ(store.progress(), Progress{});
    EXPECT_EQ(store.settings(), Settings{});
    EXPECT_TRUE(store.takeMessages().empty());
    EXPECT_FALSE(std::filesystem::exists(dir / "abalike")) << "loading creates nothing";
}

TEST(SaveStore, PinnedSettingsAreUsedAndNeverWritten)
{
    const TempDir dir;
    writeText(dir / "class.json", R"({"format": 1, "text_scale": 1.5})");
    SaveStore store(dir / "abalike");
    store.load();
    store.pinSettings(readSettingsFile(dir / "class.json"));
    EXPECT_EQ(store.settings().textScale, 1.5);
    Settings changed = store.settings();
    changed.fullscreen = true;
    EXPECT_TRUE(store.saveSettings(changed));
    EXPECT_TRUE(store.settings().fullscreen) << "kept for this run";
    EXPECT_FALSE(std::filesystem::exists(store.settingsPath())) << "never written";
    EXPECT_EQ(readText(dir / "class.json"), R"({"format": 1, "text_scale": 1.5})");

    writeText(dir / "bad.json", R"({"format": 1, "text_scale": "big"})");
    try
    {
        readSettingsFile(dir / "bad.json");
        FAIL() << "a bad settings file must throw";
    }
    catch (const SaveFormatError& e)
    {
        EXPECT_EQ(std::string(e.what()).rfind((dir / "bad.json").string() + ": /text_scale: expected", 0), 0u)
            << e.what();
    }
    EXPECT_THROW(readSettingsFile(dir / "none.json"), SaveIoError);
}

TEST(SaveStore, SavesAndLoadsBackCreatingTheFolder)
{
    const TempDir dir;
    Settings settings;
    settings.fullscreen = true;
    {
        SaveStore store(dir / "deep" / "abalike");
        store.load();
        EXPECT_TRUE(store.saveProgress(someProgress()));
        EXPECT_TRUE(store.saveSettings(settings));
        EXPECT_TRUE(store.takeMessages().empty());
    }
    SaveStore again(dir / "deep" / "abalike");
    again.load();
    EXPECT_EQ(again.progress(), someProgress());
    EXPECT_EQ(again.settings(), settings);
    EXPECT_EQ(entries(dir / "deep" / "abalike"), (std::vector<std::string>{"progress.json", "settings.json"}));
}

TEST(SaveStore, ADamagedFileIsKeptAsideAndDefaultsAreUsed)
{
    const TempDir dir;
    const std::string damaged = R"({"format": 1, "levels": {"1-1": {"best_score": 24)";
    writeText(dir / "progress.json", damaged);
    SaveStore store(dir.path());
    store.load();
    EXPECT_EQ(store.progress(), Progress{});
    const auto messages = store.takeMessages();
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_NE(messages[0].find("progress.json is damaged (not valid JSON"), std::string::npos) << messages[0];
    EXPECT_NE(messages[0].find("it was kept as " + (dir / "progress.json.corrupt-").string()), std::string::npos)
        << messages[0];

    const auto names = entries(dir.path());
    ASSERT_EQ(names.size(), 1u);
    EXPECT_EQ(names[0].rfind("progress.json.corrupt-", 0), 0u) << names[0];
    EXPECT_EQ(readText(dir / names[0]), damaged) << "the player's bytes are kept as they were";

    // The next save writes a fresh file and leaves the backup alone.
    EXPECT_TRUE(store.saveProgress(someProgress()));
    EXPECT_EQ(entries(dir.path()).size(), 2u);
    EXPECT_EQ(readText(dir / names[0]), damaged);
}

TEST(SaveStore, AScriptedRunLeavesADamagedFileExactlyAsItWas)
{
    const TempDir dir;
    const std::string damaged = R"({"text_scale": 2.0})"; // no "format"
    writeText(dir / "settings.json", damaged);
    SaveStore store(dir.path());
    store.load(SaveStore::Damaged::LeaveAlone);
    EXPECT_EQ(store.settings(), Settings{});
    const auto messages = store.takeMessages();
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_NE(messages[0].find("settings.json is damaged (missing \"format\")"), std::string::npos) << messages[0];
    EXPECT_NE(messages[0].find("leaves the file untouched"), std::string::npos) << messages[0];
    ASSERT_EQ(entries(dir.path()), std::vector<std::string>{"settings.json"}) << "nothing renamed or added";
    EXPECT_EQ(readText(dir / "settings.json"), damaged);
    // And a save in that state never overwrites it.
    EXPECT_FALSE(store.saveSettings(Settings{}));
    EXPECT_EQ(readText(dir / "settings.json"), damaged);
}

TEST(SaveStore, TwoDamagedFilesInOneSecondKeepBothBackups)
{
    const TempDir dir;
    writeText(dir / "settings.json", "first damage");
    SaveStore(dir.path()).load();
    writeText(dir / "settings.json", "second damage");
    SaveStore(dir.path()).load();
    const auto names = entries(dir.path());
    ASSERT_EQ(names.size(), 2u) << joined(names);
    EXPECT_NE(readText(dir / names[0]), readText(dir / names[1]));
}

TEST(SaveStore, WrongValuesCountAsDamage)
{
    const TempDir dir;
    writeText(dir / "settings.json", R"({"format": 1, "music_volume": 3})");
    SaveStore store(dir.path());
    store.load();
    EXPECT_EQ(store.settings(), Settings{});
    const auto messages = store.takeMessages();
    EXPECT_TRUE(anyContains(messages, "/music_volume: expected a number from 0")) << joined(messages);
}

TEST(SaveStore, AnUnreadableFileIsNeverOverwritten)
{
    const TempDir dir;
    // A directory where the file should be cannot be read; as root, permissions would not stop a read.
    std::filesystem::create_directories(dir / "progress.json" / "keep");
    SaveStore store(dir.path());
    store.load();
    EXPECT_TRUE(anyContains(store.takeMessages(), "Cannot read the progress file"));
    EXPECT_FALSE(store.saveProgress(someProgress()));
    EXPECT_EQ(store.progress(), someProgress()) << "the game keeps playing with the progress in memory";
    EXPECT_TRUE(anyContains(store.takeMessages(), "left untouched"));
    EXPECT_TRUE(std::filesystem::exists(dir / "progress.json" / "keep"));
    EXPECT_TRUE(store.saveSettings(Settings{})) << "the other file is unaffected";
}

TEST(SaveStore, AFifoInPlaceOfTheFileDoesNotHang)
{
    const TempDir dir;
    ASSERT_EQ(::mkfifo((dir / "settings.json").c_str(), 0600), 0);
    SaveStore store(dir.path());
    store.load();
    EXPECT_TRUE(anyContains(store.takeMessages(), "not a regular file"));
}

TEST(SaveStore, AFolderThatCannotBeCreatedGivesOneMessageAndTheGameGoesOn)
{
    const TempDir dir;
    writeText(dir / "file", "a file, not a folder");
    SaveStore store(dir / "file" / "abalike");
    store.load();
    EXPECT_TRUE(store.takeMessages().empty());
    EXPECT_FALSE(store.saveProgress(someProgress()));
    EXPECT_FALSE(store.saveProgress(someProgress()));
    const auto messages = store.takeMessages();
    ASSERT_EQ(messages.size(), 1u) << "a repeated failure is reported once: " << joined(messages);
    EXPECT_NE(messages[0].find("Your progress was not saved: cannot create the folder"), std::string::npos)
        << messages[0];
    EXPECT_EQ(store.progress(), someProgress());
}

TEST(SaveStore, AReadOnlyFolderGivesAMessage)
{
    if (::geteuid() == 0)
        GTEST_SKIP() << "root writes into read-only folders; the full-disk and not-a-folder tests cover this path";
    const TempDir dir;
    std::filesystem::permissions(dir.path(), std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    SaveStore store(dir.path());
    store.load();
    EXPECT_FALSE(store.saveSettings(Settings{}));
    EXPECT_TRUE(anyContains(store.takeMessages(), "Permission denied"));
}

TEST(SaveStore, AFullDiskKeepsTheLastGoodFile)
{
    const TempDir dir;
    SaveStore store(dir.path());
    store.load();
    ASSERT_TRUE(store.saveProgress(someProgress()));
    const std::string good = readText(dir / "progress.json");
    Progress more = someProgress();
    for (int i = 0; i < 1000; ++i)
        more.record("level-" + std::to_string(i), i, 1);
    {
        const test::FileSizeLimit full(good.size() + 10);
        EXPECT_FALSE(store.saveProgress(more));
    }
    EXPECT_TRUE(anyContains(store.takeMessages(), "File too large"));
    EXPECT_EQ(readText(dir / "progress.json"), good);
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"progress.json"});
    EXPECT_TRUE(store.saveProgress(more)) << "space is back: the next save works";
    SaveStore again(dir.path());
    again.load();
    EXPECT_EQ(again.progress(), more);
}

TEST(SaveStore, NoKnownFolderMeansNoSavingButNoFailure)
{
    SaveStore store{std::filesystem::path()};
    store.load();
    EXPECT_TRUE(anyContains(store.takeMessages(), "No folder for saved games is known"));
    EXPECT_FALSE(store.saveProgress(someProgress()));
    EXPECT_FALSE(std::filesystem::exists("progress.json"));
}

TEST(SaveStore, AHugeFileIsSetAsideWithoutReadingIt)
{
    const TempDir dir;
    writeText(dir / "progress.json", std::string(5u << 20, ' '));
    SaveStore store(dir.path());
    store.load();
    EXPECT_TRUE(anyContains(store.takeMessages(), "is larger than"));
    EXPECT_EQ(entries(dir.path()).size(), 1u);
}

} // namespace
} // namespace abalike
