// The level editor driven by scripted input under a virtual display (`abalike edit --script`), checked through the
// files it writes and the run's trace.
#include "RunGame.hpp"

#include <gtest/gtest.h>

namespace abalike::test
{
namespace
{

const std::string kSize = " --size 1280x720";

std::string readText(const std::filesystem::path& path)
{
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

int runCheck(const std::string& file)
{
    std::string command = "'";
    command += ABALIKE_EXECUTABLE;
    command += "' check '" + file + "' >/dev/null 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class EditorFlow : public ::testing::Test
{
protected:
    EditorFlow() : m_dir(::testing::UnitTest::GetInstance()->current_test_info()->name())
    {
        std::filesystem::create_directories(data());
    }
    std::filesystem::path data() const { return m_dir.path() / "data"; }
    std::string script(const std::string& json) const
    {
        const std::string path = m_dir.write("script.json", json);
        return " --script '" + path + "'";
    }
    GameRun edit(const std::string& args) const { return runGame("edit " + args + kSize, data()); }
    GameRun play(const std::string& args) const { return runGame("play " + args + kSize, data()); }

    ScratchDir m_dir;
};

TEST_F(EditorFlow, AScriptedRunPlacesTwoBlocksAndAPigAndSaves)
{
    // The palette's "Stone box" button (a click through the ImGui bridge), then a click near the ground puts a 1 m
    // stone box there. B (the block tool, still stone), a click above it stacks the second on the first. P: the pig
    // tool, a click to its right. Ctrl+S saves to the file named on the command line.
    const std::string file = m_dir.file("built.json");
    const GameRun run = edit("'" + file + "' --frames 60" + script(R"([
        {"frame": 8, "mouse": "press", "button": "left", "x": 56, "y": 221},
        {"frame": 8, "mouse": "release", "button": "left", "x": 56, "y": 221},
        {"frame": 12, "mouse": "move", "x": 560, "y": 610},
        {"frame": 14, "mouse": "press", "button": "left", "x": 560, "y": 610},
        {"frame": 15, "mouse": "release", "button": "left", "x": 560, "y": 610},
        {"frame": 20, "key": "B"},
        {"frame": 22, "mouse": "press", "button": "left", "x": 566, "y": 575},
        {"frame": 23, "mouse": "release", "button": "left", "x": 566, "y": 575},
        {"frame": 30, "key": "P"},
        {"frame": 32, "mouse": "press", "button": "left", "x": 700, "y": 615},
        {"frame": 33, "mouse": "release", "button": "left", "x": 700, "y": 615},
        {"frame": 40, "key": "S", "ctrl": true}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("editor-place", "object"), (std::vector<std::string>{"/blocks/0", "/blocks/1", "/pigs/0"}));
    EXPECT_EQ(run.values("editor-save", "path"), (std::vector<std::string>{file}));
    const nlohmann::json level = nlohmann::json::parse(readText(file));
    ASSERT_EQ(level["blocks"].size(), 2u);
    ASSERT_EQ(level["pigs"].size(), 1u);
    // Snapped: the first box on the ground, the second exactly on the first, the pig on the ground.
    EXPECT_EQ(level["blocks"][0]["y"].get<double>(), 0.5);
    EXPECT_EQ(level["blocks"][1]["y"].get<double>(), 1.5);
    EXPECT_EQ(level["pigs"][0]["y"].get<double>(), 0.25);
    EXPECT_EQ(level["blocks"][0]["material"], "stone");
    EXPECT_EQ(level["blocks"][1]["material"], "stone");
    EXPECT_EQ(runCheck(file), 0) << readText(file);
    // Scripted runs never write the player's files: no autosave, no imgui.ini.
    EXPECT_TRUE(std::filesystem::is_empty(data()));
}

TEST_F(EditorFlow, TheTitleMenuOpensTheSandboxAndLevelSelectOpensTheEditor)
{
    // Title: Play, Level select, Tutorial, Lessons, Sandbox and editor, ...
    const GameRun sandbox = play("--frames 20" + script(R"([{"frame": 2, "key": "Down"}, {"frame": 3, "key": "Down"},
        {"frame": 4, "key": "Down"}, {"frame": 5, "key": "Down"}, {"frame": 6, "key": "Enter"}])"));
    ASSERT_EQ(sandbox.exitCode, 0) << sandbox.err;
    EXPECT_EQ(sandbox.finalScreens(), (std::vector<std::string>{"title", "editor"}));
    EXPECT_EQ(sandbox.values("editor", "level"), (std::vector<std::string>{"sandbox"}));

    const GameRun select = play("--frames 20" + script(R"([{"frame": 2, "key": "Down"}, {"frame": 3, "key": "Enter"},
        {"frame": 6, "key": "E"}])"));
    ASSERT_EQ(select.exitCode, 0) << select.err;
    EXPECT_EQ(select.finalScreens(), (std::vector<std::string>{"title", "level-select", "editor"}));
    EXPECT_EQ(select.values("editor", "level"), (std::vector<std::string>{"1-1"}));
}

TEST_F(EditorFlow, PlayingFromTheEditorReturnsToTheExactScene)
{
    // Save a copy once as it opened, and once after playing it (F5, fire with Space, watch, Esc): the same bytes.
    const std::string before = m_dir.file("before.json");
    const std::string after = m_dir.file("after.json");
    std::filesystem::copy_file(sourceFile("levels/1-1-first-flight.json"), before);
    std::filesystem::copy_file(sourceFile("levels/1-1-first-flight.json"), after);
    const GameRun plain = edit("'" + before + "' --frames 10" + script(R"([{"frame": 3, "key": "S", "ctrl": true}])"));
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    const GameRun played = edit("'" + after + "' --frames 260" + script(R"([{"frame": 3, "key": "F5"},
        {"frame": 10, "key": "Space"}, {"frame": 240, "key": "Escape"}, {"frame": 250, "key": "S", "ctrl": true}])"));
    ASSERT_EQ(played.exitCode, 0) << played.err;
    EXPECT_EQ(played.values("launch", "speed").size(), 1u) << "one bird was fired";
    EXPECT_EQ(played.values("editor-play", "level").size(), 1u);
    EXPECT_EQ(played.values("editor-edit", "level").size(), 1u);
    EXPECT_EQ(readText(after), readText(before));
}

TEST_F(EditorFlow, UnsavedChangesAreNeverDroppedSilently)
{
    // Esc with nothing selected leaves the editor; with unsaved changes it asks first, and the editor stays.
    const std::string file = m_dir.file("scene.json");
    const GameRun clean = edit("'" + file + "' --frames 20" + script(R"([{"frame": 3, "key": "Escape"}])"));
    ASSERT_EQ(clean.exitCode, 0) << clean.err;
    EXPECT_TRUE(clean.finalScreens().empty()) << "left at once: nothing to lose";

    const GameRun changed = edit("'" + file + "' --frames 30" + script(R"([{"frame": 3, "key": "P"},
        {"frame": 5, "mouse": "press", "button": "left", "x": 640, "y": 640},
        {"frame": 6, "mouse": "release", "button": "left", "x": 640, "y": 640},
        {"frame": 10, "key": "Escape"}, {"frame": 12, "key": "Escape"}])"));
    ASSERT_EQ(changed.exitCode, 0) << changed.err;
    EXPECT_EQ(changed.finalScreens(), (std::vector<std::string>{"editor"})) << "the prompt keeps it open";
    EXPECT_FALSE(std::filesystem::exists(file)) << "nothing was saved without being asked";
}

TEST_F(EditorFlow, ALevelWithGeometryProblemsOpensWithThemListed)
{
    const std::string file = sourceFile("tests/level/malformed/overlapping-blocks.json");
    const GameRun run = edit("'" + file + "' --frames 5");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("overlaps /blocks/0"), std::string::npos) << run.err;
    EXPECT_EQ(run.finalScreens(), (std::vector<std::string>{"editor"}));
}

} // namespace
} // namespace abalike::test
