// The game's screens driven by scripted input (`abalike play --script`) under a virtual display, checked through
// the run's trace: which screens were pushed and popped, which levels started, what was saved.
#include "RunGame.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>
#include <regex>

namespace abalike::test
{
namespace
{

/// A PNG's width and height, from the IHDR chunk's big-endian fields at bytes 16 and 20.
std::vector<int> pngSize(const std::string& path)
{
    std::ifstream png(path, std::ios::binary);
    unsigned char bytes[24] = {};
    png.read(reinterpret_cast<char*>(bytes), sizeof bytes);
    const auto be = [&bytes](int at)
    {
        return (bytes[at] << 24) | (bytes[at + 1] << 16) | (bytes[at + 2] << 8) | bytes[at + 3];
    };
    return std::vector<int>{be(16), be(20)};
}

class ScreenFlow : public ::testing::Test
{
protected:
    ScreenFlow() : m_dir(::testing::UnitTest::GetInstance()->current_test_info()->name())
    {
        std::filesystem::create_directories(data());
    }
    std::filesystem::path data() const { return m_dir.path() / "data"; }
    std::string script(const std::string& json) const { return " --script '" + m_dir.write("script.json", json) + "'"; }
    GameRun play(const std::string& args) const { return runGame("play " + args + kWindowSize, data()); }

    ScratchDir m_dir;
};

TEST_F(ScreenFlow, NoLevelOpensTheTitleAlsoWithFramesAndScripts)
{
    const GameRun run = play("--frames 5");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.finalScreens(), (std::vector<std::string>{"title"}));
    EXPECT_TRUE(run.values("level", "id").empty()) << "no level starts by itself";
}

TEST_F(ScreenFlow, AQuestionMarkOnTheHelpClosesOnlyTheHelp)
{
    // A real '?' is a key press (Slash with Shift), its text, and the release, in one frame. Pressed twice, and
    // after F1, it toggles the help over the level and never closes the level too (issue 57: it popped play).
    const std::string question = R"({"frame": F, "key": "Slash", "shift": true, "action": "press"},
        {"frame": F, "text": "?"}, {"frame": F, "key": "Slash", "shift": true, "action": "release"})";
    std::string events;
    for (const int frame : {5, 10, 20, 30})
        events += (events.empty() ? "" : ", ") + std::regex_replace(question, std::regex("F"), std::to_string(frame));
    const GameRun run = play(sourceFile("levels/1-1-first-flight.json") + " --frames 40" +
                             script("[" + events + R"(, {"frame": 15, "key": "F1"}, {"frame": 25, "key": "F1"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    // ? opens, ? closes, F1 opens, ? closes, F1 opens, ? closes.
    EXPECT_EQ(run.values("push", "screen"), (std::vector<std::string>{"play", "help", "help", "help"}));
    EXPECT_EQ(run.values("pop", "screen"), (std::vector<std::string>{"help", "help", "help"}));
    EXPECT_EQ(run.finalScreens(), (std::vector<std::string>{"play"}));
}

TEST_F(ScreenFlow, PlayThenPauseThenResume)
{
    const GameRun run = play("--frames 40" + script(R"([{"frame": 2, "key": "Enter"},
        {"frame": 10, "key": "Escape"}, {"frame": 20, "key": "Escape"}, {"frame": 30, "key": "P"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("level", "id"), (std::vector<std::string>{"1-1"})) << "Play starts the first level";
    EXPECT_EQ(run.values("push", "screen"), (std::vector<std::string>{"title", "play", "pause", "pause"}));
    EXPECT_EQ(run.values("pop", "screen"), (std::vector<std::string>{"pause"}));
    EXPECT_EQ(run.finalScreens(), (std::vector<std::string>{"title", "play", "pause"}));
}

TEST_F(ScreenFlow, LevelSelectAndBackWithKeysAndWithTheMouse)
{
    // Down to "Level select", Enter; Escape back to the title.
    const GameRun keys = play("--frames 20" + script(R"([{"frame": 2, "key": "Down"}, {"frame": 3, "key": "Enter"},
        {"frame": 10, "key": "Escape"}])"));
    ASSERT_EQ(keys.exitCode, 0) << keys.err;
    EXPECT_EQ(keys.values("push", "screen"), (std::vector<std::string>{"title", "level-select"}));
    EXPECT_EQ(keys.finalScreens(), (std::vector<std::string>{"title"}));

    // The same with the mouse: hover and click the second button, then click the first tile (level 1-1).
    const GameRun mouse = play("--frames 30" + script(R"([
        {"frame": 2, "mouse": "move", "x": 640, "y": 289},
        {"frame": 3, "mouse": "press", "button": "left", "x": 640, "y": 289},
        {"frame": 4, "mouse": "release", "button": "left", "x": 640, "y": 289},
        {"frame": 10, "mouse": "press", "button": "left", "x": 349, "y": 115},
        {"frame": 11, "mouse": "release", "button": "left", "x": 349, "y": 115}])"));
    ASSERT_EQ(mouse.exitCode, 0) << mouse.err;
    EXPECT_EQ(mouse.finalScreens(), (std::vector<std::string>{"title", "level-select", "play"}));
    EXPECT_EQ(mouse.values("level", "id"), (std::vector<std::string>{"1-1"}));
}

TEST_F(ScreenFlow, ALockedLevelDoesNotStart)
{
    // 1-2 is locked for a new player: Right, Enter does nothing.
    const GameRun run = play("--frames 20" + script(R"([{"frame": 2, "key": "Down"}, {"frame": 3, "key": "Enter"},
        {"frame": 5, "key": "Right"}, {"frame": 6, "key": "Enter"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(run.values("level", "id").empty());
    EXPECT_EQ(run.finalScreens(), (std::vector<std::string>{"title", "level-select"}));
}

TEST_F(ScreenFlow, HelpOpensAnywhereAndAnyKeyClosesIt)
{
    const GameRun run = play("--frames 30" + script(R"([{"frame": 2, "key": "F1"}, {"frame": 5, "key": "Space"},
        {"frame": 8, "text": "?"}, {"frame": 12, "key": "F1"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("push", "screen"), (std::vector<std::string>{"title", "help", "help"}));
    EXPECT_EQ(run.values("pop", "screen"), (std::vector<std::string>{"help", "help"}));
    EXPECT_EQ(run.finalScreens(), (std::vector<std::string>{"title"}));
}

TEST_F(ScreenFlow, TheToolbarAndTheRightButtonGiveTheMouseEveryMenuKey)
{
    // The pause button (top right) pauses, a right click backs out (resume), the ? button opens help, a right click
    // closes it. Buttons are 34 px squares 6 px apart, 10 px from the top right corner at 1280x720.
    const std::string level = sourceFile("levels/1-1-first-flight.json");
    const GameRun run = play(std::string("'").append(level).append("' --frames 40") + script(R"([
        {"frame": 2, "mouse": "press", "button": "left", "x": 1253, "y": 27},
        {"frame": 3, "mouse": "release", "button": "left", "x": 1253, "y": 27},
        {"frame": 10, "mouse": "press", "button": "right", "x": 640, "y": 360},
        {"frame": 11, "mouse": "release", "button": "right", "x": 640, "y": 360},
        {"frame": 20, "mouse": "press", "button": "left", "x": 1213, "y": 27},
        {"frame": 21, "mouse": "release", "button": "left", "x": 1213, "y": 27},
        {"frame": 30, "mouse": "press", "button": "right", "x": 640, "y": 360},
        {"frame": 31, "mouse": "release", "button": "right", "x": 640, "y": 360}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("push", "screen"), (std::vector<std::string>{"play", "pause", "help"}));
    EXPECT_EQ(run.values("pop", "screen"), (std::vector<std::string>{"pause", "help"}));
    EXPECT_TRUE(run.values("launch", "angle_deg").empty()) << "a click on a button never aims or launches";
    EXPECT_EQ(run.finalScreens(), (std::vector<std::string>{"play"}));
}

TEST_F(ScreenFlow, SettingsFromTheTitleApplyAtOnceAndAScriptedRunNeverWritesThem)
{
    // Title: Settings is the sixth entry. In settings (effects volume first: the game has no music): down to Text
    // size, Right; Colours, Enter; High contrast, Right; then Escape back to the title.
    const GameRun run = play("--frames 26" + script(R"([
        {"frame": 2, "key": "Down"}, {"frame": 3, "key": "Down"}, {"frame": 4, "key": "Down"},
        {"frame": 5, "key": "Down"}, {"frame": 6, "key": "Down"}, {"frame": 7, "key": "Enter"},
        {"frame": 9, "key": "Down"}, {"frame": 10, "key": "Down"}, {"frame": 11, "key": "Down"},
        {"frame": 12, "key": "Down"}, {"frame": 14, "key": "Right"},
        {"frame": 15, "key": "Down"}, {"frame": 16, "key": "Enter"}, {"frame": 17, "key": "Down"},
        {"frame": 18, "key": "Right"}, {"frame": 20, "key": "Escape"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("push", "screen"), (std::vector<std::string>{"title", "settings"}));
    EXPECT_EQ(run.values("pop", "screen"), (std::vector<std::string>{"settings"}));
    EXPECT_EQ(run.values("settings", "text_scale"), (std::vector<std::string>{"1.25", "1.25", "1.25"}));
    EXPECT_EQ(run.values("settings", "palette"),
              (std::vector<std::string>{"standard", "colour_blind_safe", "colour_blind_safe"}));
    EXPECT_EQ(run.values("settings", "high_contrast"), (std::vector<std::string>{"false", "false", "true"}));
    EXPECT_EQ(run.finalScreens(), (std::vector<std::string>{"title"}));
    EXPECT_FALSE(std::filesystem::exists(data() / "settings.json")) << "a scripted run never writes the settings";
}

TEST_F(ScreenFlow, TheSizeOnTheCommandLineWinsOverTheSavedSize)
{
    std::ofstream(data() / "settings.json") << R"({"format": 1, "window": [960, 540]})";
    const std::string saved = m_dir.file("saved.png");
    const GameRun savedRun = runGame("play --frames 2 --screenshot '" + saved + "'", data());
    ASSERT_EQ(savedRun.exitCode, 0) << savedRun.err;
    EXPECT_EQ(pngSize(saved), (std::vector<int>{960, 540}));
    const std::string given = m_dir.file("given.png");
    const GameRun givenRun = runGame("play --frames 2 --size 800x600 --screenshot '" + given + "'", data());
    ASSERT_EQ(givenRun.exitCode, 0) << givenRun.err;
    EXPECT_EQ(pngSize(given), (std::vector<int>{800, 600}));
}

TEST_F(ScreenFlow, ASettingsFileOnTheCommandLineWinsOverTheSavedSettingsAndIsNeverWritten)
{
    // What a live session saved (a window size, the overlay on) must not reach a class's prepared script.
    const std::string saved = R"({"format": 1, "window": [960, 540], "teaching_overlay": true})";
    std::ofstream(data() / "settings.json") << saved;
    const std::string pinned = m_dir.write("class.json", R"({"format": 1, "window": [800, 600]})");
    const std::string shot = m_dir.file("pinned.png");
    const GameRun run = runGame("play --frames 2 --settings '" + pinned + "' --screenshot '" + shot + "'", data());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(pngSize(shot), (std::vector<int>{800, 600}));
    std::stringstream after;
    after << std::ifstream(data() / "settings.json").rdbuf();
    EXPECT_EQ(after.str(), saved);

    const std::string broken = m_dir.write("broken.json", R"({"format": 1, "window": [800, "tall"]})");
    const GameRun bad = runGame("play --frames 2 --settings '" + broken + "'", data());
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("--settings: " + broken + ": /window/1: expected"), std::string::npos) << bad.err;
    const GameRun missing = runGame("play --frames 2 --settings '" + m_dir.file("none.json") + "'", data());
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.err.find("none.json: no such file"), std::string::npos) << missing.err;
}

TEST_F(ScreenFlow, HoldingFPlaysTheFreeFlightThreeTimesFasterWithTheSamePhysics)
{
    // The Moon's long flight: with F held the same defeats happen at the same game time, in fewer frames.
    const std::string args = "'" + sourceFile("levels/5-1-the-moon.json") + "' --shot 42.5,9 --frames 500";
    const GameRun plain = play(args);
    const GameRun fast = play(args + script(R"([{"frame": 5, "key": "F", "action": "press"}])"));
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    ASSERT_EQ(fast.exitCode, 0) << fast.err;
    const std::vector<std::string> times = plain.values("defeat", "t");
    ASSERT_FALSE(times.empty());
    // The fast run gets further in its frames: what both saw happened at the same game times.
    std::vector<std::string> fastTimes = fast.values("defeat", "t");
    ASSERT_GE(fastTimes.size(), times.size());
    fastTimes.resize(times.size());
    EXPECT_EQ(fastTimes, times) << "the physics is unchanged";
    const int plainFrame = std::stoi(plain.values("defeat", "frame").front());
    const int fastFrame = std::stoi(fast.values("defeat", "frame").front());
    // About 7 s of free flight after the launch at frame 30: two thirds of its frames are saved.
    EXPECT_LT(fastFrame, 30 + (plainFrame - 30) / 2) << plainFrame << " vs " << fastFrame;
}

TEST_F(ScreenFlow, ALevelOnTheCommandLineGoesStraightToIt)
{
    const std::string level = sourceFile("levels/2-8-dominoes.json");
    const GameRun run = play(std::string("'").append(level).append("' --frames 5"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.finalScreens(), (std::vector<std::string>{"play"}));
    EXPECT_EQ(run.values("level", "id"), (std::vector<std::string>{"2-8"}));
}

TEST_F(ScreenFlow, ShotsWithoutALevelStartTheCampaignAndAWinLeadsOn)
{
    // 1-1 as the solver wins it (abalike solve): two shots, decided at frame 740; then N goes to 1-2, where the
    // shots, which belong to the level the run opened on, fire nothing.
    const GameRun run = play("--shot 30,18 --shot 5,30 --frames 900" + script(R"([{"frame": 770, "key": "N"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("finished", "won"), (std::vector<std::string>{"true"})) << "the two shots win 1-1";
    EXPECT_EQ(run.values("level", "id"), (std::vector<std::string>{"1-1", "1-2"}));
    EXPECT_EQ(run.values("launch", "angle_deg").size(), 2u) << "nothing fired on 1-2";
    EXPECT_EQ(run.finalScreens(), (std::vector<std::string>{"play"}));
}

TEST_F(ScreenFlow, TheSourceFileOfACampaignLevelIsThatLevel)
{
    // The build plays a staged copy of levels/; a designer names the source file. Same bytes: the same campaign
    // level, so its result counts and "next level" follows. A level of their own is not in the campaign.
    const GameRun source =
        play(std::string("'").append(sourceFile("levels/1-1-first-flight.json")).append("' --frames 3"));
    ASSERT_EQ(source.exitCode, 0) << source.err;
    EXPECT_EQ(source.values("level", "campaign_index"), (std::vector<std::string>{"0"}));
    std::ifstream original(sourceFile("levels/1-1-first-flight.json"));
    const std::string text((std::istreambuf_iterator<char>(original)), std::istreambuf_iterator<char>());
    const std::string own = m_dir.write("own.json", text + "\n");
    const GameRun copy = play("'" + own + "' --frames 3");
    ASSERT_EQ(copy.exitCode, 0) << copy.err;
    EXPECT_EQ(copy.values("level", "id"), (std::vector<std::string>{"1-1"}));
    EXPECT_TRUE(copy.values("level", "campaign_index").empty()) << "one byte more is another file";
}

TEST_F(ScreenFlow, ScriptedRunsReadTheSavedProgressButNeverWriteIt)
{
    const std::string progress = R"({
  "format": 1,
  "levels": {"1-1": {"best_score": 1000, "stars": 1}},
  "unlocked": ["1-1", "1-2"]
}
)";
    std::ofstream(data() / "progress.json") << progress;
    // 1-2 is unlocked by the saved progress, and level select opens on it (1-1 already has its star).
    const GameRun run = play("--frames 20" + script(R"([{"frame": 2, "key": "Down"}, {"frame": 3, "key": "Enter"},
        {"frame": 6, "key": "Enter"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("level", "id"), (std::vector<std::string>{"1-2"}));
    std::stringstream after;
    after << std::ifstream(data() / "progress.json").rdbuf();
    EXPECT_EQ(after.str(), progress);
    EXPECT_FALSE(std::filesystem::exists(data() / "settings.json"));
}

TEST_F(ScreenFlow, AMalformedScriptExitsTwoWithALocatedError)
{
    const GameRun run = play("--frames 5" + script("[{\"frame\": 1, \"key\": \"Escpe\"}]"));
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("script.json:1:22: error: /0/key: unknown key name \"Escpe\" (did you mean \"Escape\"?)"),
              std::string::npos)
        << run.err;
    EXPECT_TRUE(run.trace.empty()) << "no window opens for a bad script";
}

TEST_F(ScreenFlow, PlayPackOpensThePacksFirstUnfinishedLevelAndInstalledPacksFollowTheCampaign)
{
    // A pack of two levels (1-1 and 1-2 under the ids p-1 and p-2, episode "A"), its first level won before.
    const std::filesystem::path pack = m_dir.path() / "mypack";
    std::filesystem::create_directories(pack);
    const std::filesystem::path levels = std::filesystem::path(ABALIKE_SOURCE_DIR) / "levels";
    int n = 0;
    for (const char* from : {"1-1-first-flight.json", "1-2-the-long-shot.json"})
    {
        std::ifstream in(levels / from);
        nlohmann::json level = nlohmann::json::parse(in);
        level["id"] = "p-" + std::to_string(++n);
        level["episode"] = "A";
        std::ofstream(pack / ("l" + std::to_string(n) + ".json")) << level.dump(2);
    }
    std::ofstream(pack / "campaign.json")
        << R"({"format": 1, "episodes": [{"id": "A", "levels": ["l1.json", "l2.json"]}]})";
    std::ofstream(data() / "progress.json")
        << R"({"format": 1, "levels": {"mypack/p-1": {"best_score": 30000, "stars": 2}}, "unlocked": ["1-1", "mypack/p-1", "mypack/p-2"]})";
    const GameRun run = play("--pack '" + pack.string() + "' --frames 3");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("level", "id"), (std::vector<std::string>{"p-2"}));
    EXPECT_EQ(run.values("level", "campaign_index"), (std::vector<std::string>{"51"})) << "after the 50 bundled levels";

    // Installed (copied into the data folder's packs/), it follows the campaign in every run.
    std::filesystem::create_directories(data() / "packs");
    std::filesystem::copy(pack, data() / "packs" / "mypack", std::filesystem::copy_options::recursive);
    const GameRun installed = play("--pack '" + (data() / "packs" / "mypack").string() + "' --frames 3");
    ASSERT_EQ(installed.exitCode, 0) << installed.err;
    EXPECT_EQ(installed.values("level", "id"), (std::vector<std::string>{"p-2"}));
    EXPECT_EQ(installed.err.find("does not load"), std::string::npos) << installed.err;
}

TEST_F(ScreenFlow, PlayLevelOpensACampaignLevelByItsNumberEvenLocked)
{
    // 3-4 is the fourth tile of episode 3 (Gusts): its id, its file's name and its title all say 3-4.
    const GameRun run = play("--level 3-4 --frames 3");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("level", "number"), (std::vector<std::string>{"3-4"}));
    EXPECT_EQ(run.values("level", "id"), (std::vector<std::string>{"3-4"}));
    EXPECT_EQ(run.values("level", "campaign_index"), (std::vector<std::string>{"19"}));
    bool titled = false;
    for (const nlohmann::json& line : run.trace)
        if (line.value("event", "") == "texts")
            for (const nlohmann::json& text : line["shown"])
                titled = titled || text.get<std::string>() == "Level 3-4: Gusts";
    EXPECT_TRUE(titled);
}

TEST_F(ScreenFlow, ATimedLevelThatRunsOutSaysOutOfTimeAndTheTraceSaysWhy)
{
    const std::string level = m_dir.write("timed.json", R"({"format": 1, "id": "timed", "title": "Timed",
        "slingshot": {"x": 0, "y": 1.5}, "birds": ["red", "red"], "pigs": [{"x": 20, "y": 0.25}], "time_limit_s": 1.5})");
    const GameRun run = play(level + " --frames 160");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("finished", "reason"), (std::vector<std::string>{"out_of_time"}));
    std::string texts;
    for (const nlohmann::json& line : run.trace)
        if (line.value("event", "") == "texts")
            for (const nlohmann::json& text : line["shown"])
                texts += text.get<std::string>() + "\n";
    EXPECT_NE(texts.find("Out of time (2 s)"), std::string::npos) << texts;
}

TEST_F(ScreenFlow, TheResultsCardIgnoresASpaceHeldFromTheShotAndItsFirstHalfSecond)
{
    // This shot wins 3-1 (the results open at frame 301; the trace says why it finished). Space goes down at frame
    // 262 for the ability and stays down; R at the card's first frames is ignored too; after half a second R
    // restarts as always.
    const GameRun run = play(sourceFile("levels/3-1-tailwind.json") + " --shot 30,30 --frames 357" +
                             script(R"([{"frame": 262, "key": "Space", "action": "press"},
        {"frame": 304, "key": "R"}, {"frame": 317, "key": "Space", "action": "release"}, {"frame": 347, "key": "R"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("finished", "reason"), (std::vector<std::string>{"won"}));
    std::vector<int> restarts;
    for (const nlohmann::json& line : run.trace)
        if (line.value("event", "") == "restart")
            restarts.push_back(line.value("frame", 0));
    ASSERT_EQ(restarts.size(), 1u) << "only the late R restarts";
    EXPECT_GE(restarts.front(), 347);
}

TEST_F(ScreenFlow, QuittingFromARunningLevelAsksFirst)
{
    // Pause, then Quit game (the last item: Up from the first wraps to it): the game asks instead of quitting.
    const std::string level = sourceFile("levels/1-1-first-flight.json") + " --frames 40";
    const GameRun asked = play(level + script(R"([{"frame": 5, "key": "Escape"}, {"frame": 8, "key": "Up"},
        {"frame": 10, "key": "Enter"}])"));
    ASSERT_EQ(asked.exitCode, 0) << asked.err;
    EXPECT_EQ(asked.finalScreens(), (std::vector<std::string>{"play", "pause"}));
    EXPECT_EQ(asked.values("exit", "code"), (std::vector<std::string>{"0"}));
    // Keep playing is the first answer and Escape too; the second answer quits.
    const GameRun quit = play(level + script(R"([{"frame": 5, "key": "Escape"}, {"frame": 8, "key": "Up"},
        {"frame": 10, "key": "Enter"}, {"frame": 12, "key": "Down"}, {"frame": 14, "key": "Enter"}])"));
    ASSERT_EQ(quit.exitCode, 0) << quit.err;
    EXPECT_LT(quit.trace.back().value("frame", 0), 20);
    const GameRun kept = play(level + script(R"([{"frame": 5, "key": "Escape"}, {"frame": 8, "key": "Up"},
        {"frame": 10, "key": "Enter"}, {"frame": 12, "key": "Escape"}, {"frame": 14, "key": "Escape"}])"));
    EXPECT_EQ(kept.finalScreens(), (std::vector<std::string>{"play"}));
}

} // namespace
} // namespace abalike::test
