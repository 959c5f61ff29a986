// The level editor driven by scripted input under a virtual display (`abalike edit --script`), checked through the
// files it writes and the run's trace.
#include "RunGame.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace abalike::test
{
namespace
{

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
    GameRun edit(const std::string& args) const { return runGame("edit " + args + kWindowSize, data()); }
    GameRun play(const std::string& args) const { return runGame("play " + args + kWindowSize, data()); }

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

TEST_F(EditorFlow, GenerateHereDropsAStandingStructureAsOneUndoStep)
{
    // Insert > Generate here > towers > medium (up to 20): a structure of the generator's layouts, verified to stand,
    // in hand until a click on the scene drops it there, onto the ground; Ctrl+S saves it. The second run generates
    // two and takes the second back with one Ctrl+Z: what it saves is the first run's structure.
    const auto generateAt = [](int frame)
    {
        std::string steps;
        for (const auto& [dt, event] : std::vector<std::pair<int, std::string>>{
                 {0, R"("mouse": "move", "x": 114, "y": 11)"},
                 {1, R"("mouse": "press", "button": "left", "x": 114, "y": 11)"},
                 {1, R"("mouse": "release", "button": "left", "x": 114, "y": 11)"},
                 {3, R"("mouse": "move", "x": 130, "y": 126)"},
                 {5, R"("mouse": "move", "x": 330, "y": 126)"},
                 {7, R"("mouse": "move", "x": 460, "y": 146)"},
                 {8, R"("mouse": "press", "button": "left", "x": 460, "y": 146)"},
                 {8, R"("mouse": "release", "button": "left", "x": 460, "y": 146)"},
                 {12, R"("mouse": "move", "x": 700, "y": 300)"},
                 {13, R"("mouse": "press", "button": "left", "x": 700, "y": 300)"},
                 {13, R"("mouse": "release", "button": "left", "x": 700, "y": 300)"}})
            steps += "{\"frame\": " + std::to_string(frame + dt) + ", " + event + "},\n";
        return steps;
    };
    const std::string file = m_dir.file("generated.json");
    const GameRun run = edit("'" + file + "' --frames 24" + script("[" + generateAt(4) + R"(
        {"frame": 19, "key": "S", "ctrl": true}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("editor-generate", "kind"), (std::vector<std::string>{"towers"}));
    EXPECT_EQ(run.values("editor-generate", "error"), (std::vector<std::string>{"false"}));
    const nlohmann::json saved = nlohmann::json::parse(readText(file));
    const std::size_t bodies = saved["blocks"].size() + saved["pigs"].size();
    EXPECT_GE(bodies, 8u);
    EXPECT_LE(bodies, 20u);
    EXPECT_GE(saved["pigs"].size(), 1u);
    double left = 1e9, right = -1e9;
    for (const auto& block : saved["blocks"])
    {
        EXPECT_GE(block["y"].get<double>() - 0.5 * block["h"].get<double>(), -1e-9) << "on the ground, not in it";
        left = std::min(left, block["x"].get<double>() - 0.5 * block["w"].get<double>());
        right = std::max(right, block["x"].get<double>() + 0.5 * block["w"].get<double>());
    }
    // Where the click was (right of the view's centre, where it went when the menu dropped it at once): the
    // structure's middle within a grid step (0.25 m) of it.
    const std::vector<std::string> droppedAt = run.values("editor-drop", "x");
    ASSERT_EQ(droppedAt.size(), 1u);
    EXPECT_NEAR(0.5 * (left + right), std::stod(droppedAt[0]), 0.25 + 1e-9);

    const std::string twice = m_dir.file("twice.json");
    const GameRun undo = edit("'" + twice + "' --frames 44" + script("[" + generateAt(4) + generateAt(20) + R"(
        {"frame": 36, "key": "Z", "ctrl": true},
        {"frame": 38, "key": "S", "ctrl": true}])"));
    ASSERT_EQ(undo.exitCode, 0) << undo.err;
    EXPECT_EQ(undo.values("editor-generate", "seed"), (std::vector<std::string>{"1", "2"}));
    EXPECT_EQ(nlohmann::json::parse(readText(twice))["blocks"], saved["blocks"]) << "one Ctrl+Z takes a structure";
}

TEST_F(EditorFlow, TypingFasterThanTheFramesLosesNoKey)
{
    // The designer's finding: at about 12 frames a second, 20 Backspaces deleted one character and Ctrl+A then
    // typing appended. Dear ImGui 1.86 reads keys once a frame, so the bridge queues them: 20 keys and characters at
    // two a frame into the level's Title field (Ctrl+A, "Mesa Towerx", Backspace, "s", Home, "A", Delete, End,
    // two Backspaces) come out exactly, at most 40 frames after the last one.
    const std::string file = m_dir.file("typed.json");
    const GameRun run = edit("'" + file + "' --frames 70" + script(R"([
        {"frame": 2, "mouse": "press", "button": "left", "x": 53, "y": 399},
        {"frame": 2, "mouse": "release", "button": "left", "x": 53, "y": 399},
        {"frame": 4, "mouse": "press", "button": "left", "x": 700, "y": 615},
        {"frame": 4, "mouse": "release", "button": "left", "x": 700, "y": 615},
        {"frame": 6, "mouse": "press", "button": "left", "x": 1166, "y": 63},
        {"frame": 6, "mouse": "release", "button": "left", "x": 1166, "y": 63},
        {"frame": 9, "mouse": "press", "button": "left", "x": 1050, "y": 115},
        {"frame": 9, "mouse": "release", "button": "left", "x": 1050, "y": 115},
        {"frame": 12, "key": "A", "ctrl": true}, {"frame": 12, "text": "M"},
        {"frame": 13, "text": "e"}, {"frame": 13, "text": "s"},
        {"frame": 14, "text": "a"}, {"frame": 14, "text": " "},
        {"frame": 15, "text": "T"}, {"frame": 15, "text": "o"},
        {"frame": 16, "text": "w"}, {"frame": 16, "text": "e"},
        {"frame": 17, "text": "r"}, {"frame": 17, "text": "x"},
        {"frame": 18, "key": "Backspace"}, {"frame": 18, "text": "s"},
        {"frame": 19, "key": "Home"}, {"frame": 19, "text": "A"},
        {"frame": 20, "key": "Delete"}, {"frame": 20, "key": "End"},
        {"frame": 21, "key": "Backspace"}, {"frame": 21, "key": "Backspace"},
        {"frame": 61, "key": "Enter"},
        {"frame": 65, "key": "S", "ctrl": true}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    ASSERT_EQ(run.values("editor-save", "path"), (std::vector<std::string>{file})) << run.err;
    const nlohmann::json level = nlohmann::json::parse(readText(file));
    EXPECT_EQ(level["title"], "Aesa Towe");
}

TEST_F(EditorFlow, WidthOnAHillScalesItsCorners)
{
    // The designer's finding: Width on a polygon hill took the value and saved nothing. 2-3's hill, 13 m wide about
    // x = 22.5, typed 19.5 m wide: its corners scale by 1.5 about its centre.
    const std::string file = m_dir.file("hill.json");
    std::filesystem::copy_file(sourceFile("levels/2-3-boulder-hill.json"), file);
    const GameRun run = edit("'" + file + "' --frames 30" + script(R"([
        {"frame": 3, "mouse": "press", "button": "left", "x": 590, "y": 610},
        {"frame": 3, "mouse": "release", "button": "left", "x": 590, "y": 610},
        {"frame": 6, "mouse": "press", "button": "left", "x": 1050, "y": 150},
        {"frame": 6, "mouse": "release", "button": "left", "x": 1050, "y": 150},
        {"frame": 9, "key": "A", "ctrl": true}, {"frame": 11, "text": "19.5"}, {"frame": 16, "key": "Enter"},
        {"frame": 22, "key": "S", "ctrl": true}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    ASSERT_EQ(run.values("editor-save", "path"), (std::vector<std::string>{file}));
    const nlohmann::json level = nlohmann::json::parse(readText(file));
    const std::vector<std::array<double, 2>> scaled{{12.75, 0.0}, {32.25, 0.0}, {25.2, 3.0}, {17.25, 3.0}};
    const auto& points = level["terrain"][0]["points"];
    ASSERT_EQ(points.size(), scaled.size()) << points;
    for (std::size_t i = 0; i < scaled.size(); ++i)
        for (std::size_t axis = 0; axis < 2; ++axis)
            EXPECT_NEAR(points[i][axis].get<double>(), scaled[i][axis], 1e-9) << points;
}

TEST_F(EditorFlow, TheTitleMenuOpensTheSandboxAndLevelSelectOpensTheEditor)
{
    // Title: Play, Level select, Endless castles, Learn, Sandbox and editor, ...
    const GameRun sandbox = play("--frames 21" + script(R"([{"frame": 2, "key": "Down"}, {"frame": 3, "key": "Down"},
        {"frame": 4, "key": "Down"}, {"frame": 5, "key": "Down"}, {"frame": 7, "key": "Enter"}])"));
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
    // (Zoomed in first, so that the view has to follow the bird.)
    const GameRun played =
        edit("'" + after + "' --frames 260" + script(R"([{"frame": 2, "wheel": 6, "x": 500, "y": 500},
        {"frame": 3, "key": "F5"}, {"frame": 10, "key": "Space"}, {"frame": 240, "key": "Escape"},
        {"frame": 250, "key": "S", "ctrl": true}])"));
    ASSERT_EQ(played.exitCode, 0) << played.err;
    EXPECT_EQ(played.values("launch", "speed").size(), 1u) << "one bird was fired";
    EXPECT_EQ(played.values("editor-play", "level").size(), 1u);
    EXPECT_EQ(played.values("editor-edit", "level").size(), 1u);
    EXPECT_EQ(readText(after), readText(before));
    // The view followed the bird, and came back with the scene.
    ASSERT_EQ(played.values("editor-edit", "view").size(), 1u);
    EXPECT_EQ(played.values("editor-edit", "view"), played.values("editor-play", "view"));
    EXPECT_NE(played.values("editor-edit", "play_view"), played.values("editor-play", "view"));
}

TEST_F(EditorFlow, ThePalettesBirdsJoinTheLaunchOrderAsUndoableEdits)
{
    // The palette's "Blue" bird button (beside its colour, under the pigs) clicked twice, Ctrl+Z once, Ctrl+S: the
    // level keeps its birds and gains one blue bird at the end.
    const std::string file = m_dir.file("birds.json");
    std::filesystem::copy_file(sourceFile("levels/1-1-first-flight.json"), file);
    const std::vector<std::string> before = nlohmann::json::parse(readText(file)).at("birds");
    const GameRun run = edit("'" + file + "' --frames 30" + script(R"([
        {"frame": 6, "mouse": "press", "button": "left", "x": 165, "y": 479},
        {"frame": 6, "mouse": "release", "button": "left", "x": 165, "y": 479},
        {"frame": 10, "mouse": "press", "button": "left", "x": 165, "y": 479},
        {"frame": 10, "mouse": "release", "button": "left", "x": 165, "y": 479},
        {"frame": 14, "key": "Z", "ctrl": true},
        {"frame": 18, "key": "S", "ctrl": true}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    std::vector<std::string> expected = before;
    expected.push_back("blue");
    EXPECT_EQ(nlohmann::json::parse(readText(file)).at("birds").get<std::vector<std::string>>(), expected);
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

TEST_F(EditorFlow, SavingALevelThatDoesNotStandSaysWhatCheckWillSay)
{
    // 1-1 with its highest block 5 cm up, opened and saved as it is: the save runs the rest test and lists its
    // finding in `abalike check`'s words, with the verified fix; the trace carries the same.
    nlohmann::json level = nlohmann::json::parse(readText(sourceFile("levels/1-1-first-flight.json")));
    nlohmann::json* top = &level["blocks"][0];
    for (nlohmann::json& block : level["blocks"])
        if (block["y"].get<double>() > (*top)["y"].get<double>())
            top = &block;
    (*top)["y"] = (*top)["y"].get<double>() + 0.05;
    const std::string file = m_dir.write("floating.json", level.dump(2));
    const GameRun run = edit("'" + file + "' --frames 20" + script(R"([{"frame": 10, "key": "S", "ctrl": true}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::vector<std::string> findings = run.values("editor-save", "rest_findings");
    ASSERT_EQ(findings.size(), 1u);
    const nlohmann::json listed = nlohmann::json::parse(findings[0]);
    ASSERT_EQ(listed.size(), 1u) << findings[0];
    EXPECT_EQ(listed[0].get<std::string>().rfind("floats 5.0 cm above block", 0), 0u) << listed[0];
    EXPECT_NE(listed[0].get<std::string>().find("; set y = "), std::string::npos) << listed[0];
}

TEST_F(EditorFlow, ALevelWithGeometryProblemsOpensWithThemListed)
{
    const std::string file = sourceFile("tests/level/malformed/overlapping-blocks.json");
    const GameRun run = edit("'" + file + "' --frames 5");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("overlaps /blocks/0"), std::string::npos) << run.err;
    EXPECT_EQ(run.finalScreens(), (std::vector<std::string>{"editor"}));
}

TEST_F(EditorFlow, PrefabsMirrorAndPolygonCornersWorkWithTheMouseAndFindingsFollowEveryEdit)
{
    // Insert > My prefabs > lean-to (from the data folder's prefabs/; a submenu) in hand, a click drops it on the
    // ground in the scene's middle, Ctrl+M mirrors it, the wheel zooms, a
    // right drag pans, a click selects the hill, its top-left corner is dragged up; Ctrl+S saves. The level opened with
    // an overlap, which the re-check after each edit keeps finding. (tools/gallery takes docs/img/editor-tools.png from
    // the same steps.)
    const std::string file = m_dir.file("hillside.json");
    std::filesystem::copy_file(sourceFile("tests/window/data/editor-hillside.json"), file);
    std::filesystem::create_directories(data() / "prefabs");
    std::filesystem::copy_file(sourceFile("tests/window/data/lean-to-prefab.json"),
                               data() / "prefabs" / "lean-to.json");
    const GameRun run = edit("'" + file + "' --frames 42" + script(R"([
        {"frame": 8, "mouse": "move", "x": 114, "y": 11},
        {"frame": 9, "mouse": "press", "button": "left", "x": 114, "y": 11},
        {"frame": 9, "mouse": "release", "button": "left", "x": 114, "y": 11},
        {"frame": 10, "mouse": "move", "x": 130, "y": 102},
        {"frame": 12, "mouse": "move", "x": 340, "y": 102},
        {"frame": 13, "mouse": "press", "button": "left", "x": 340, "y": 102},
        {"frame": 13, "mouse": "release", "button": "left", "x": 340, "y": 102},
        {"frame": 15, "mouse": "move", "x": 575, "y": 560},
        {"frame": 16, "mouse": "press", "button": "left", "x": 575, "y": 560},
        {"frame": 16, "mouse": "release", "button": "left", "x": 575, "y": 560},
        {"frame": 17, "key": "M", "ctrl": true},
        {"frame": 18, "mouse": "move", "x": 560, "y": 600},
        {"frame": 19, "wheel": 2, "x": 560, "y": 600},
        {"frame": 20, "wheel": 2, "x": 560, "y": 600},
        {"frame": 22, "mouse": "move", "x": 800, "y": 300},
        {"frame": 23, "mouse": "press", "button": "right", "x": 800, "y": 300},
        {"frame": 24, "mouse": "move", "x": 700, "y": 250},
        {"frame": 25, "mouse": "move", "x": 560, "y": 200},
        {"frame": 26, "mouse": "release", "button": "right", "x": 560, "y": 200},
        {"frame": 28, "mouse": "move", "x": 700, "y": 510},
        {"frame": 29, "mouse": "press", "button": "left", "x": 700, "y": 510},
        {"frame": 29, "mouse": "release", "button": "left", "x": 700, "y": 510},
        {"frame": 31, "mouse": "move", "x": 562, "y": 468},
        {"frame": 32, "mouse": "press", "button": "left", "x": 562, "y": 468},
        {"frame": 33, "mouse": "move", "x": 570, "y": 450},
        {"frame": 34, "mouse": "move", "x": 578, "y": 436},
        {"frame": 35, "mouse": "release", "button": "left", "x": 578, "y": 436},
        {"frame": 37, "mouse": "move", "x": 640, "y": 250},
        {"frame": 38, "key": "S", "ctrl": true}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("editor-prefab", "error"), (std::vector<std::string>{"false"}));
    const nlohmann::json saved = nlohmann::json::parse(readText(file));
    const nlohmann::json& blocks = saved["blocks"];
    ASSERT_EQ(blocks.size(), 6u);
    ASSERT_EQ(saved["pigs"].size(), 2u);
    // Mirrored: the stone post is now the right one, the ramp's right angle at the bottom right (legs swapped, a
    // quarter turn).
    EXPECT_EQ(blocks[2]["material"], "stone");
    EXPECT_EQ(blocks[5]["material"], "ice");
    EXPECT_GT(blocks[2]["x"].get<double>(), blocks[5]["x"].get<double>());
    EXPECT_EQ(blocks[3]["shape"], "triangle");
    EXPECT_EQ(blocks[3]["angle_deg"].get<double>(), 90.0);
    EXPECT_EQ(blocks[3]["w"].get<double>(), 1.0);
    // The hill's corner at (27, 2.5) went up, on the grid; the others stayed.
    const nlohmann::json& points = saved["terrain"][0]["points"];
    ASSERT_EQ(points.size(), 6u);
    EXPECT_GT(points[5][1].get<double>(), 2.5);
    EXPECT_EQ(std::fmod(points[5][1].get<double>(), 0.25), 0.0);
    EXPECT_EQ(points[2], nlohmann::json::parse("[37, 3]"));
    // The geometry check ran again after the edits and still finds the overlap the level opened with.
    const std::vector<std::string> rechecks = run.values("editor-recheck", "geometry_findings");
    ASSERT_GE(rechecks.size(), 3u);  // the insert, the mirror, the corner
    EXPECT_EQ(rechecks.back(), "2"); // the overlap marks both blocks
}

} // namespace
} // namespace abalike::test
