// The teaching aids in the real game, driven by scripted input under a virtual display and checked through the
// run's trace: the tutorial and the lessons open from the title, T toggles the teaching_overlay setting, the RK4
// walkthrough holds the world still, and every teaching key works in flight without a crash.
#include "RunGame.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include <filesystem>
#include <gtest/gtest.h>
#include <regex>

namespace abalike::test
{
namespace
{

class TeachFlow : public ::testing::Test
{
protected:
    TeachFlow() : m_dir(::testing::UnitTest::GetInstance()->current_test_info()->name())
    {
        std::filesystem::create_directories(data());
    }
    std::filesystem::path data() const { return m_dir.path() / "data"; }
    std::string script(const std::string& json) const { return " --script '" + m_dir.write("script.json", json) + "'"; }
    /// The teaching flows check what the learn mode shows: they say so (the game mode is the default).
    GameRun play(const std::string& args) const
    {
        return runGame("play " + args + kWindowSize + " --mode learn", data());
    }
    GameRun playGame(const std::string& args) const
    {
        return runGame("play " + args + kWindowSize + " --mode game", data());
    }

    ScratchDir m_dir;
};

TEST_F(TeachFlow, TutorialAndLessonsOpenFromTheTitlesLearn)
{
    // Title: Play, Level select, Endless castles, Learn, ...; Learn: the campaign with its physics, Tutorial,
    // Lessons, Back.
    const GameRun tutorial = playGame("--frames 15" + script(R"([{"frame": 2, "key": "Down"},
        {"frame": 3, "key": "Down"}, {"frame": 4, "key": "Down"}, {"frame": 5, "key": "Enter"},
        {"frame": 7, "key": "Down"}, {"frame": 8, "key": "Enter"}])"));
    ASSERT_EQ(tutorial.exitCode, 0) << tutorial.err;
    EXPECT_EQ(tutorial.values("level", "id"), (std::vector<std::string>{"tutorial"}));
    EXPECT_EQ(tutorial.finalScreens(), (std::vector<std::string>{"title", "learn", "play"}));

    // Lessons, then the fourth lesson (wind).
    const GameRun lessons = playGame("--frames 23" + script(R"([{"frame": 2, "key": "Down"},
        {"frame": 3, "key": "Down"}, {"frame": 4, "key": "Down"}, {"frame": 5, "key": "Enter"},
        {"frame": 7, "key": "Down"}, {"frame": 8, "key": "Down"}, {"frame": 9, "key": "Enter"},
        {"frame": 11, "key": "Down"}, {"frame": 12, "key": "Down"}, {"frame": 13, "key": "Down"},
        {"frame": 14, "key": "Enter"}])"));
    ASSERT_EQ(lessons.exitCode, 0) << lessons.err;
    EXPECT_EQ(lessons.values("push", "screen"), (std::vector<std::string>{"title", "learn", "lessons", "play"}));
    EXPECT_EQ(lessons.values("level", "id"), (std::vector<std::string>{"lesson-wind"}));
}

namespace
{
/// The kinds of the texts the run's last frame showed, by text.
std::vector<std::pair<std::string, std::string>> shownKinds(const GameRun& run)
{
    std::vector<std::pair<std::string, std::string>> shown;
    for (const nlohmann::json& line : run.trace)
        if (line.value("event", "") == "texts")
            for (std::size_t i = 0; i < line["shown"].size(); ++i)
                shown.emplace_back(line["shown"][i].get<std::string>(), line["kinds"][i].get<std::string>());
    return shown;
}
} // namespace

TEST_F(TeachFlow, TheTutorialHasItsOwnLevelAndEveryStepCanBeDone)
{
    // Angle, power, launch, T, a path reading (M), a second launch at the same aim (it strikes the stone block, as
    // the first did: "hit a pig" stays), a third 1.2 m/s faster onto the medium pig: the sixth step done, the
    // tutorial is kept as finished (a "result" for "tutorial"), so nothing starts it again. Its three pigs stand
    // apart, so the first shot does not end the level on step 5 as 1-1 under another name did.
    const GameRun run = play(sourceFile("levels/lessons/tutorial.json") + " --frames 1200" + script(R"([
        {"frame": 200, "key": "Up"}, {"frame": 204, "key": "Right"}, {"frame": 208, "key": "Space"},
        {"frame": 215, "key": "T"}, {"frame": 260, "key": "M"}, {"frame": 620, "key": "Space"},
        {"frame": 1000, "key": "Right"}, {"frame": 1002, "key": "Right"}, {"frame": 1004, "key": "Right"},
        {"frame": 1006, "key": "Right"}, {"frame": 1020, "key": "Space"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("level", "id"), (std::vector<std::string>{"tutorial"}));
    EXPECT_EQ(run.values("launch", "frame"), (std::vector<std::string>{"208", "620", "1020"}));
    EXPECT_EQ(run.values("result", "level"), (std::vector<std::string>{"tutorial"}));
    const std::vector<std::string> finished = run.values("result", "frame");
    ASSERT_EQ(finished.size(), 1u);
    EXPECT_GT(std::stoi(finished.front()), 1020) << "a miss does not finish the tutorial";
    EXPECT_EQ(run.finalScreens(), (std::vector<std::string>{"play"})) << "the level goes on after the tutorial";
}

TEST_F(TeachFlow, ASettingsNoticeReplacesItsEarlierOne)
{
    // Z twice: slow motion at a half, then a quarter. Only the last speed is on screen, not both at once.
    const GameRun run = play(sourceFile("levels/1-1-first-flight.json") + " --frames 20" +
                             script(R"([{"frame": 2, "key": "Z"}, {"frame": 5, "key": "Z"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    int speeds = 0;
    bool quarter = false;
    for (const auto& [text, kind] : shownKinds(run))
        if (text.rfind("Speed ", 0) == 0)
        {
            ++speeds;
            quarter = text.rfind("Speed \u00BC\u00D7", 0) == 0;
        }
    EXPECT_EQ(speeds, 1);
    EXPECT_TRUE(quarter);
}

TEST_F(TeachFlow, TheGameModeShowsNoPhysicsSentenceOrFormulaAndTheLearnModeDoes)
{
    // 1-1 after its reference shot, the next bird being aimed: the feedback sentences, the aim readout and the air.
    const std::string args = sourceFile("levels/1-1-first-flight.json") + " --shot 30,18 --frames 330";
    const GameRun game = playGame(args);
    ASSERT_EQ(game.exitCode, 0) << game.err;
    const GameRun learn = play(args);
    ASSERT_EQ(learn.exitCode, 0) << learn.err;
    int hud = 0;
    for (const auto& [text, kind] : shownKinds(game))
    {
        EXPECT_NE(kind, "physics") << "game mode shows: " << text;
        EXPECT_NE(kind, "formula") << "game mode shows: " << text;
        EXPECT_EQ(text.find("m/s"), std::string::npos) << "game mode shows units: " << text;
        hud += kind == "hud" ? 1 : 0;
    }
    EXPECT_GE(hud, 3) << "the level, the score, the birds and pigs, the aim";
    int physics = 0;
    int formula = 0;
    bool feedback = false;
    for (const auto& [text, kind] : shownKinds(learn))
    {
        physics += kind == "physics" ? 1 : 0;
        formula += kind == "formula" ? 1 : 0;
        feedback = feedback || (kind == "physics" && text.find("The bird hit") != std::string::npos);
    }
    EXPECT_TRUE(feedback) << "the feedback sentence on the shot's first contact";
    EXPECT_GE(physics, 2) << "the aim's numbers and the sentences on the shot";
    EXPECT_EQ(formula, 1) << "F = k x, E = 1/2 F x, ...";
}

TEST_F(TeachFlow, TTogglesTheTeachingOverlaySetting)
{
    const GameRun run = play(sourceFile("levels/1-1-first-flight.json") + " --frames 10" +
                             script(R"([{"frame": 2, "key": "T"}, {"frame": 5, "key": "T"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("settings", "teaching_overlay"), (std::vector<std::string>{"true", "false"}));
    // A scripted run never writes the player's files.
    EXPECT_FALSE(std::filesystem::exists(data() / "settings.json"));
}

namespace
{
/// Every text the run's last frame showed, joined by newlines.
std::string shownTexts(const GameRun& run)
{
    std::string all;
    for (const nlohmann::json& line : run.trace)
        if (line.value("event", "") == "texts")
            for (const nlohmann::json& text : line["shown"])
                all += text.get<std::string>() + "\n";
    return all;
}
} // namespace

TEST_F(TeachFlow, SchoolWordingNamesNoMachineryAndUniversityDoes)
{
    // In flight with the teaching overlay: forces, energy, the why panel, the toolbar and its tooltip, the hint.
    const std::string args = sourceFile("levels/3-5-headwind.json") + " --shot 40,28 --frames 60" +
                             script(R"([{"frame": 2, "key": "T"}, {"frame": 3, "key": "V"},
        {"frame": 50, "mouse": "move", "x": 1000, "y": 25}])");
    const std::regex machinery(R"(RK4|Box2D|TOI|chord)");
    for (const char* wording : {"", " --wording school"})
    {
        const GameRun run = play(args + wording);
        ASSERT_EQ(run.exitCode, 0) << run.err;
        const std::string texts = shownTexts(run);
        EXPECT_NE(texts.find("Why preview and world can differ"), std::string::npos) << texts;
        EXPECT_FALSE(std::regex_search(texts, machinery)) << texts;
    }
    const GameRun university = play(args + " --wording university");
    ASSERT_EQ(university.exitCode, 0) << university.err;
    EXPECT_TRUE(std::regex_search(shownTexts(university), machinery)) << shownTexts(university);

    // The help screen lists the integrator tools only at university wording.
    const std::string help =
        sourceFile("levels/3-5-headwind.json") + " --frames 10" + script(R"([{"frame": 2, "key": "F1"}])");
    const GameRun schoolHelp = play(help);
    ASSERT_EQ(schoolHelp.exitCode, 0) << schoolHelp.err;
    EXPECT_NE(shownTexts(schoolHelp).find("Controls"), std::string::npos) << shownTexts(schoolHelp);
    EXPECT_FALSE(std::regex_search(shownTexts(schoolHelp), machinery)) << shownTexts(schoolHelp);
    // Its second page has the teaching rows (PageDown).
    const std::string helpPage2 = sourceFile("levels/3-5-headwind.json") + " --frames 10" +
                                  script(R"([{"frame": 2, "key": "F1"}, {"frame": 4, "key": "PageDown"}])");
    const GameRun schoolPage2 = play(helpPage2);
    EXPECT_NE(shownTexts(schoolPage2).find("Slow motion"), std::string::npos) << shownTexts(schoolPage2);
    EXPECT_FALSE(std::regex_search(shownTexts(schoolPage2), machinery)) << shownTexts(schoolPage2);
    const GameRun universityPage2 = play(helpPage2 + " --wording university");
    EXPECT_NE(shownTexts(universityPage2).find("RK4 walkthrough"), std::string::npos) << shownTexts(universityPage2);

    // A wrong word is a usage error, not a silent default.
    const GameRun wrong = play(help + " --wording college");
    EXPECT_EQ(wrong.exitCode, 2);
    EXPECT_NE(wrong.err.find("--wording: expected school or university, got \"college\""), std::string::npos)
        << wrong.err;
}

TEST_F(TeachFlow, SlowMotionStepsTheSameWorldAtAFractionOfThePace)
{
    // The same shot at real time and at half speed (Z): the same defeats at the same game times, each shown about
    // twice as many frames later. Slow motion shows the physics more slowly; it does not change it.
    const std::string level = sourceFile("levels/3-1-tailwind.json") + " --shot 30,30";
    const GameRun real = play(level + " --frames 290");
    const GameRun half = play(level + " --frames 580" + script(R"([{"frame": 1, "key": "Z"}])"));
    ASSERT_EQ(real.exitCode, 0) << real.err;
    ASSERT_EQ(half.exitCode, 0) << half.err;
    const auto defeats = [](const GameRun& run)
    {
        std::vector<nlohmann::json> list;
        for (nlohmann::json line : run.trace)
            if (line.value("event", "") == "defeat")
                list.push_back(line);
        return list;
    };
    const std::vector<nlohmann::json> atReal = defeats(real);
    const std::vector<nlohmann::json> atHalf = defeats(half);
    ASSERT_GE(atReal.size(), 3u);
    ASSERT_EQ(atHalf.size(), atReal.size());
    for (std::size_t i = 0; i < atReal.size(); ++i)
    {
        const int realFrame = atReal[i]["frame"].get<int>();
        const int halfFrame = atHalf[i]["frame"].get<int>();
        EXPECT_NEAR(halfFrame, 2 * realFrame, 4) << i;
        nlohmann::json a = atReal[i], b = atHalf[i];
        a.erase("frame");
        b.erase("frame");
        EXPECT_EQ(a, b) << i;
    }
}

TEST_F(TeachFlow, TheExportKeyWritesEveryShotAsCsvInTheDataFolder)
{
    const GameRun run =
        play(sourceFile("levels/3-1-tailwind.json") + " --shot 30,30 --frames 200" +
             script(R"([{"frame": 1, "key": "E"}, {"frame": 150, "key": "E"}, {"frame": 160, "key": "E"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    // Before the first shot there is nothing to export, and it says so; then two exports, never overwritten.
    EXPECT_NE(run.err.find("No shot to export yet"), std::string::npos) << run.err;
    const std::filesystem::path first = data() / "exports" / "3-1-shots-1.csv";
    const std::filesystem::path second = data() / "exports" / "3-1-shots-2.csv";
    ASSERT_TRUE(std::filesystem::exists(first)) << run.err;
    ASSERT_TRUE(std::filesystem::exists(second));
    std::ifstream in(first);
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header, "shot,t_s,x_m,y_m,vx_mps,vy_mps,ax_mps2,ay_mps2,speed_mps,kinetic_j,potential_j,drag_work_j,"
                      "contact,contact_acts");
    int rows = 0;
    for (std::string line; std::getline(in, line);)
        rows += line.rfind("1,", 0) == 0 ? 1 : 0;
    EXPECT_GT(rows, 60); // more than a second of flight at 1/60 s
}

TEST_F(TeachFlow, PredictThenLaunchSetsThePredictionAgainstTheFlightAndTheFormula)
{
    // The lesson: type 23.5, lock it with Enter, and the scripted shot at 35 degrees and 16 m/s comes back to its
    // launch height at v^2 sin 2a / g = 24.52 m; the world's flight measures the same, and the card says where.
    const GameRun run = play(sourceFile("levels/lessons/lesson-predict.json") + " --shot 35,16 --frames 200" +
                             script(R"([{"frame": 3, "text": "23.5"}, {"frame": 5, "key": "Enter"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string texts = shownTexts(run);
    const double range = 16.0 * 16.0 * std::sin(70.0 * M_PI / 180.0) / 9.81;
    char expected[32];
    std::snprintf(expected, sizeof expected, "%.2f m", range);
    EXPECT_NE(texts.find("you predicted\n23.50 m"), std::string::npos) << texts;
    EXPECT_NE(texts.find(std::string("measured on the flight\n") + expected), std::string::npos) << texts;
    EXPECT_NE(texts.find(std::string("the formula gives\n") + expected), std::string::npos) << texts;
    EXPECT_NE(texts.find("until its centre is back at the launch height"), std::string::npos) << texts;
    EXPECT_NE(texts.find("back to the launch height " + std::string(expected).substr(0, 4) + " m away"),
              std::string::npos)
        << texts;
}

TEST_F(TeachFlow, TheTutorialCompletesEvenWithTheOverlayHiddenAgain)
{
    // A new player: aim, power, launch, the overlay on and off again, a tape with the right button, a second launch
    // 4 % harder, onto the medium pig (the last step wants a pig hit, not any launch). The measuring step used to wait
    // for the overlay forever; and a single 0.5 degree key step must count as aiming.
    // Title: Learn (the fourth entry), then its Tutorial.
    const GameRun run = play("--frames 520" + script(R"([{"frame": 2, "key": "Down"}, {"frame": 3, "key": "Down"},
        {"frame": 4, "key": "Down"}, {"frame": 5, "key": "Enter"}, {"frame": 7, "key": "Down"},
        {"frame": 8, "key": "Enter"}, {"frame": 15, "key": "Up"}, {"frame": 17, "key": "Right"},
        {"frame": 19, "key": "Space"}, {"frame": 25, "key": "T"}, {"frame": 35, "key": "T"},
        {"frame": 45, "mouse": "press", "button": "right", "x": 300, "y": 500},
        {"frame": 50, "mouse": "move", "x": 500, "y": 500},
        {"frame": 55, "mouse": "release", "button": "right", "x": 500, "y": 500}, {"frame": 340, "key": "Right"},
        {"frame": 342, "key": "Right"}, {"frame": 344, "key": "Right"}, {"frame": 346, "key": "Right"},
        {"frame": 355, "key": "Space"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string texts = shownTexts(run);
    EXPECT_NE(texts.find("Tutorial: the controls\ndone\nThat is every control."), std::string::npos) << texts;
}

TEST_F(TeachFlow, TheWalkthroughHoldsTheWorldStill)
{
    // The reference shot of 3-1 wins the level in about 6 s; with the walkthrough started in flight and never left,
    // the world stands still and nothing is decided.
    const std::string level = sourceFile("levels/3-1-tailwind.json") + " --shot 30,30";
    const GameRun free = play(level + " --frames 600");
    ASSERT_EQ(free.exitCode, 0) << free.err;
    EXPECT_EQ(free.values("finished", "won"), (std::vector<std::string>{"true"}));
    const GameRun held = play(level + " --frames 600 --wording university" + script(R"([{"frame": 100, "key": "K"},
        {"frame": 110, "key": "Space"}, {"frame": 120, "key": "RBracket"}])"));
    ASSERT_EQ(held.exitCode, 0) << held.err;
    EXPECT_TRUE(held.values("finished", "won").empty());
}

TEST_F(TeachFlow, TheTraceRecordsEveryDefeatAsSimulateDoes)
{
    // The shot of SimulateCli's defeat test: the window plays the same steps, so its defeat events are simulate's
    // "defeats", field for field, except that the window launches later (the scripted pull is shown first): every
    // t is later by the same amount.
    const GameRun run = play(sourceFile("levels/1-1-first-flight.json") + " --shot 55,17 --frames 400");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    std::vector<nlohmann::json> traced;
    for (const nlohmann::json& line : run.trace)
        if (line.value("event", "") == "defeat")
        {
            nlohmann::json fields = line;
            fields.erase("event");
            fields.erase("frame");
            traced.push_back(fields);
        }
    ASSERT_GE(traced.size(), 3u);
    const std::string out = m_dir.file("simulate.json");
    // append, not "+": GCC 12 warns falsely (-Wrestrict) on operator+ with a temporary.
    std::string command = "'";
    command.append(ABALIKE_EXECUTABLE).append("' simulate '").append(sourceFile("levels/1-1-first-flight.json"));
    command.append("' --shot 55,17 --json > '").append(out).append("'");
    ASSERT_EQ(std::system(command.c_str()), 0);
    std::ifstream in(out);
    const nlohmann::json simulated = nlohmann::json::parse(in)["defeats"];
    ASSERT_GE(simulated.size(), traced.size());
    const double delay = traced[0]["t"].get<double>() - simulated[0]["t"].get<double>();
    EXPECT_GE(delay, 0.0);
    for (std::size_t i = 0; i < traced.size(); ++i)
    {
        EXPECT_NEAR(traced[i]["t"].get<double>() - simulated[i]["t"].get<double>(), delay, 1e-6) << i;
        nlohmann::json a = traced[i];
        nlohmann::json b = simulated[i];
        a.erase("t");
        b.erase("t");
        EXPECT_EQ(a, b) << i;
    }
}

TEST_F(TeachFlow, EveryTeachingKeyInFlightAndWhileAiming)
{
    const std::string shot = m_dir.file("teach.png");
    const GameRun run = play(sourceFile("levels/3-4-gusts.json") +
                             " --shot 23.8,25.5 --frames 520 --wording university --screenshot '" + shot + "'" +
                             script(R"([{"frame": 2, "key": "T"}, {"frame": 3, "key": "G"}, {"frame": 4, "key": "I"},
        {"frame": 5, "key": "LBracket"}, {"frame": 6, "key": "I"}, {"frame": 7, "key": "I"}, {"frame": 8, "key": "RBracket"},
        {"frame": 90, "mouse": "move", "x": 400, "y": 400},
        {"frame": 95, "mouse": "press", "button": "right", "x": 100, "y": 600},
        {"frame": 99, "mouse": "move", "x": 500, "y": 420},
        {"frame": 100, "mouse": "release", "button": "right", "x": 500, "y": 420},
        {"frame": 110, "key": "K"}, {"frame": 111, "key": "Space"}, {"frame": 112, "key": "LBracket"},
        {"frame": 113, "key": "LBracket"}, {"frame": 114, "key": "Space"}, {"frame": 115, "key": "Escape"},
        {"frame": 200, "key": "C"}, {"frame": 500, "key": "K"}, {"frame": 505, "key": "Space"},
        {"frame": 510, "key": "K"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.values("launch", "scripted"), (std::vector<std::string>{"true"}));
    // Esc left the walkthrough instead of opening the pause menu.
    const std::vector<std::string> pushed = run.values("push", "screen");
    EXPECT_EQ(std::count(pushed.begin(), pushed.end(), "pause"), 0);
    EXPECT_GT(std::filesystem::file_size(shot), 10000u);
}

TEST_F(TeachFlow, AfterTheImpactEveryPanelIsInsideTheWindow)
{
    // 1-3's reference shot with the overlay on: the energy and first-impact panels, the Why panel and the feedback
    // card all stand at 300 frames. The impact panel is as wide as its numbers (it once reached past the right
    // edge), the energy panel as wide as its balance line.
    const GameRun run = play(sourceFile("levels/1-3-hilltop.json") + " --frames 300 --shot 55,18" +
                             script(R"([{"frame": 2, "key": "T"}])"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const nlohmann::json* panels = nullptr;
    for (const nlohmann::json& line : run.trace)
        if (line.value("event", "") == "panels")
            panels = &line;
    ASSERT_NE(panels, nullptr);
    const double width = (*panels)["window"][0].get<double>();
    const double height = (*panels)["window"][1].get<double>();
    std::vector<std::string> names;
    for (const nlohmann::json& panel : (*panels)["drawn"])
    {
        const std::string name = panel.value("name", "");
        names.push_back(name);
        const double x = panel["x"].get<double>();
        const double y = panel["y"].get<double>();
        EXPECT_GE(x, 0.0) << name;
        EXPECT_GE(y, 0.0) << name;
        EXPECT_LE(x + panel["w"].get<double>(), width + 0.5) << name;
        EXPECT_LE(y + panel["h"].get<double>(), height + 0.5) << name;
    }
    EXPECT_NE(std::find(names.begin(), names.end(), "energy"), names.end());
    EXPECT_NE(std::find_if(names.begin(), names.end(),
                           [](const std::string& name) { return name.rfind("First impact", 0) == 0; }),
              names.end());
}

/// A panel of the last "panels" event of a run's trace: its name and rectangle in window pixels.
struct PanelBox
{
    std::string name;
    double x, y, w, h;
};

/// The panels of the run's last frame ("drawn"; "keep_visible": what they should leave visible), and the window's
/// size; fails the test when none were recorded.
std::vector<PanelBox> lastPanels(const GameRun& run, double& width, double& height, const char* list = "drawn")
{
    const nlohmann::json* panels = nullptr;
    for (const nlohmann::json& line : run.trace)
        if (line.value("event", "") == "panels")
            panels = &line;
    std::vector<PanelBox> boxes;
    EXPECT_NE(panels, nullptr);
    if (panels == nullptr)
        return boxes;
    width = (*panels)["window"][0].get<double>();
    height = (*panels)["window"][1].get<double>();
    for (const nlohmann::json& panel : (*panels)[list])
        boxes.push_back({panel.value("name", ""), panel["x"].get<double>(), panel["y"].get<double>(),
                         panel["w"].get<double>(), panel["h"].get<double>()});
    return boxes;
}

/// The first box of that name, or boxes.end().
std::vector<PanelBox>::const_iterator findBox(const std::vector<PanelBox>& boxes, const std::string& name)
{
    return std::find_if(boxes.begin(), boxes.end(), [&name](const PanelBox& box) { return box.name == name; });
}

/// Every panel inside the window and no two overlapping.
/// The last "panels" event of a run: the window, the panels drawn and what they should leave visible.
struct Layout
{
    double width = 0.0;
    double height = 0.0;
    std::vector<PanelBox> panels;
    std::vector<PanelBox> keep;
};

Layout lastLayout(const GameRun& run)
{
    Layout layout;
    layout.panels = lastPanels(run, layout.width, layout.height);
    layout.keep = lastPanels(run, layout.width, layout.height, "keep_visible");
    return layout;
}

/// Whether two boxes share no area (boxes that only touch are apart).
bool apart(const PanelBox& a, const PanelBox& b)
{
    return a.x + a.w <= b.x || b.x + b.w <= a.x || a.y + a.h <= b.y || b.y + b.h <= a.y;
}

void expectApartAndInside(const std::vector<PanelBox>& boxes, double width, double height, const std::string& what)
{
    for (std::size_t i = 0; i < boxes.size(); ++i)
    {
        const PanelBox& a = boxes[i];
        EXPECT_GE(a.x, 0.0) << what << " " << a.name;
        EXPECT_GE(a.y, 0.0) << what << " " << a.name;
        EXPECT_LE(a.x + a.w, width + 0.5) << what << " " << a.name;
        EXPECT_LE(a.y + a.h, height + 0.5) << what << " " << a.name;
        for (std::size_t j = i + 1; j < boxes.size(); ++j)
        {
            const PanelBox& b = boxes[j];
            EXPECT_TRUE(apart(a, b)) << what << ": " << a.name << " overlaps " << b.name;
        }
    }
}

TEST_F(TeachFlow, AtLargeTextALessonsGuideKeepsTheLinesThatFitAboveTheHint)
{
    // lesson-drag while aiming at 200 % text in 1280x720: the guide's card once ran into the hint at the bottom.
    // Now it keeps the lines that fit, and every panel stays apart.
    std::ofstream(data() / "settings.json") << R"({"format": 1, "text_scale": 2.0, "teaching_overlay": false})";
    const GameRun run =
        runGame("play " + sourceFile("levels/lessons/lesson-drag.json") + " --frames 20 --size 1280x720", data());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    double width = 0.0;
    double height = 0.0;
    const std::vector<PanelBox> boxes = lastPanels(run, width, height);
    expectApartAndInside(boxes, width, height, "lesson-drag 1280x720");
    EXPECT_NE(std::find_if(boxes.begin(), boxes.end(), [](const PanelBox& box) { return box.name == "guide"; }),
              boxes.end());
}

TEST_F(TeachFlow, AtLargeTextThePredictionCardShowsWhatThePlayerTypes)
{
    // lesson-predict at 200 % text in 1024x768 with the overlay on, 23.5 typed: the card once went under the wide
    // aim readout and the band graph by its column's width, found no room and was left out, so the player typed
    // blind. It now goes down by its own width and sits beside the graph, with what was typed; every panel apart.
    std::ofstream(data() / "settings.json") << R"({"format": 1, "text_scale": 2.0, "teaching_overlay": true})";
    const GameRun run = runGame("play " + sourceFile("levels/lessons/lesson-predict.json") + " --frames 20" +
                                    script(R"([{"frame": 3, "text": "23.5"}])") + " --size 1024x768",
                                data());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    double width = 0.0;
    double height = 0.0;
    const std::vector<PanelBox> boxes = lastPanels(run, width, height);
    expectApartAndInside(boxes, width, height, "lesson-predict 1024x768");
    EXPECT_NE(findBox(boxes, "Predict, then launch"), boxes.end());
    EXPECT_NE(shownTexts(run).find("23.5_ m"), std::string::npos) << shownTexts(run);
}

TEST_F(TeachFlow, AtLargeTextTheKeysAndTheHintLeaveTheSlingshotInView)
{
    // At 200 % text the keys line and a level's hint wrap to two lines each and reach above the ground line's usual
    // place: they covered the slingshot and the birds waiting by it. The camera now lifts the ground above them.
    std::ofstream(data() / "settings.json") << R"({"format": 1, "text_scale": 2.0, "teaching_overlay": true})";
    for (const std::string level : {"levels/1-3-hilltop.json", "levels/6-5-citadel.json"})
    {
        // 240 frames: past the opening pan of a wide level, back at the slingshot.
        const GameRun run = runGame("play " + sourceFile(level) + " --frames 240 --size 1280x720", data());
        ASSERT_EQ(run.exitCode, 0) << run.err;
        const auto [width, height, panels, keep] = lastLayout(run);
        const auto slingshot = findBox(keep, "slingshot");
        ASSERT_NE(slingshot, keep.end()) << level;
        EXPECT_GE(slingshot->x, 0.0) << level;
        EXPECT_LE(slingshot->y + slingshot->h, height) << level;
        std::size_t bottomText = 0;
        for (const PanelBox& panel : panels)
            if (panel.name == "keys" || panel.name == "hint")
            {
                ++bottomText;
                EXPECT_GE(panel.y, slingshot->y + slingshot->h)
                    << level << ": the " << panel.name << " covers the slingshot";
            }
        EXPECT_EQ(bottomText, 2u) << level;
    }
}

/// Seven seconds into a run of the level with the shot (the next bird ready, the camera back at the slingshot), the
/// feedback card covers none of what panels should leave visible (the trace's keep_visible).
void expectFeedbackLeavesInView(const std::filesystem::path& data, const std::string& level, const std::string& shot,
                                const std::string& size, int frames = 420)
{
    const GameRun run = runGame("play " + sourceFile(level) + " --shot " + shot + " --frames " +
                                    std::to_string(frames) + " --size " + size + " --mode learn",
                                data);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto [width, height, panels, keep] = lastLayout(run);
    const auto feedback = findBox(panels, "feedback");
    ASSERT_NE(feedback, panels.end()) << level;
    ASSERT_FALSE(keep.empty()) << level;
    for (const PanelBox& thing : keep)
    {
        EXPECT_TRUE(apart(*feedback, thing)) << level << ": the feedback covers the " << thing.name;
    }
}

TEST_F(TeachFlow, OnceTheNextBirdIsReadyTheFeedbackLeavesTheSlingshotAndThePigsInView)
{
    // 1-1 and 5-5, seven seconds into a run with the reference shot, 1280x720 at 100 % text with the overlay on: the
    // next bird is ready and the camera is back at the slingshot. The feedback card kept the spot it took when the
    // shot ended, clear of the structure as the camera framed it then, and covered a pig (tools/layout-sweep). Now
    // it moves to a spot clear of the world once the shot is over.
    std::ofstream(data() / "settings.json") << R"({"format": 1, "text_scale": 1.0, "teaching_overlay": true})";
    expectFeedbackLeavesInView(data(), "levels/1-1-first-flight.json", "30,18", "1280x720");
    expectFeedbackLeavesInView(data(), "levels/5-5-titan.json", "5,30", "1280x720");
}

TEST_F(TeachFlow, WhenTheCameraTurnsToTheStructureTheFeedbackLeavesItsPigInView)
{
    // 1-2's long shot, 280 frames in (the README's after-impact picture): the card took its spot at the first contact
    // while the camera still followed the bird, at the bottom in the middle; the camera then framed the struck frame
    // and its pig, which came to sit under the card. Now a card that comes to cover the slingshot, the bird or a pig
    // during the shot moves once to a spot clear of them.
    std::ofstream(data() / "settings.json") << R"({"format": 1, "text_scale": 1.0, "teaching_overlay": false})";
    expectFeedbackLeavesInView(data(), "levels/1-2-the-long-shot.json", "37.4,22.5", "1280x720", 280);
}

TEST_F(TeachFlow, WhenNoSpotIsClearOfTheWorldTheFeedbackStillLeavesTheSlingshotInView)
{
    // 1-1 and 6-2 in a wide, low window (1280x400) at 150 % text, seven seconds into a run with the reference shot:
    // no spot for the feedback card is clear of every block, and it kept the one it took when the shot ended, over
    // the slingshot the camera has returned to (tools/layout-sweep). Now it moves to a spot that leaves the slingshot
    // and the pigs in view, over blocks if it must.
    std::ofstream(data() / "settings.json") << R"({"format": 1, "text_scale": 1.5, "teaching_overlay": true})";
    expectFeedbackLeavesInView(data(), "levels/1-1-first-flight.json", "30,18", "1280x400");
    expectFeedbackLeavesInView(data(), "levels/6-2-powder-kegs.json", "22,22", "1280x400");
}

TEST_F(TeachFlow, AtLargeTextTheTeachingPanelsShrinkRatherThanCoverTheSlingshotTheBirdOrAPig)
{
    // 1-1 at 150 % text in 1280x720 with the overlay on: the world has little room under the columns. In flight the
    // Why panel covered the slingshot, and after the first contact the impact panel covered the struck frame's pig.
    // Now a column's panel that would cover the slingshot, the flying bird or a live pig takes its one-line summary
    // (until the next aim, so that it does not flick as the camera moves), and no panel covers them.
    std::ofstream(data() / "settings.json") << R"({"format": 1, "text_scale": 1.5, "teaching_overlay": true})";
    const auto summaryShown = [](const std::vector<PanelBox>& panels, const std::string& name)
    {
        const auto box = findBox(panels, name);
        return box != panels.end() && box->h < 80.0; // one line of 20 px text and its padding
    };
    for (const int frames : {60, 200})
    {
        const GameRun run = runGame("play " + sourceFile("levels/1-1-first-flight.json") +
                                        " --shot 30,18 --size 1280x720 --frames " + std::to_string(frames),
                                    data());
        ASSERT_EQ(run.exitCode, 0) << run.err;
        const auto [width, height, panels, keep] = lastLayout(run);
        const std::string what = "1-1 after " + std::to_string(frames) + " frames";
        expectApartAndInside(panels, width, height, what);
        ASSERT_FALSE(keep.empty()) << what;
        for (const PanelBox& thing : keep)
            for (const PanelBox& panel : panels)
                EXPECT_TRUE(apart(panel, thing))
                    << what << ": the " << panel.name << " panel covers the " << thing.name;
        if (frames == 60)
        {
            EXPECT_TRUE(summaryShown(panels, "why")) << what;
        }
        else
        {
            // After the first contact the camera turns to the struck frame: a Why panel that came over a pig then is
            // left out until the next aim (the loop above checks that none covers it), and the impact panel, too
            // tall for the room left, shows its one line.
            const auto why = findBox(panels, "why");
            EXPECT_TRUE(why == panels.end() || why->h < 80.0) << what;
            EXPECT_TRUE(summaryShown(panels, "first impact")) << what;
        }
    }
}

TEST_F(TeachFlow, AtLargeTextThePanelsAfterAShotNeverOverlapAndTheFeedbackShrinksToOneLine)
{
    // 2-8 five seconds after its reference shot, the next bird ready, at large text with the overlay on in 1280x720:
    // the whole feedback card (seven lines) once covered the status, air and aim panels, the Why panel ran into the
    // hint and the "predicted vs actual" label sat on the aim readout. Now every panel is inside the window, no two
    // overlap, and none covers a pig or the landing point (where the shot first struck). At 150 % the feedback is its
    // first sentence on one line, on the ground above the hint; at 200 % the camera lifts the ground above the wrapped
    // hint and no row of the window has room for even that line clear of the pigs and the landing point: it is left
    // out, and the Why panel's summary too. (Every level, window and text size: tests/layout.)
    for (const double textScale : {1.5, 2.0})
    {
        std::ofstream(data() / "settings.json")
            << R"({"format": 1, "text_scale": )" << textScale << R"(, "teaching_overlay": true})";
        const GameRun run = runGame("play " + sourceFile("levels/2-8-dominoes.json") +
                                        " --frames 300 --shot 32.5,12.75 --size 1280x720 --mode learn",
                                    data());
        ASSERT_EQ(run.exitCode, 0) << run.err;
        const std::string what = "2-8 1280x720 at text " + std::to_string(textScale);
        double width = 0.0;
        double height = 0.0;
        const std::vector<PanelBox> boxes = lastPanels(run, width, height);
        expectApartAndInside(boxes, width, height, what);
        const auto named = [&boxes](const std::string& name)
        {
            return std::find_if(boxes.begin(), boxes.end(), [&name](const PanelBox& box) { return box.name == name; });
        };
        ASSERT_NE(named("aim readout"), boxes.end()) << what;
        if (textScale < 2.0)
        {
            ASSERT_NE(named("feedback"), boxes.end()) << what;
            EXPECT_LT(named("feedback")->h, 60.0) << what; // one line of 24 px text and its padding, not seven
        }
        else
        {
            EXPECT_EQ(named("feedback"), boxes.end()) << what;
            EXPECT_EQ(named("why"), boxes.end()) << what;
        }
        const std::vector<PanelBox> keep = lastPanels(run, width, height, "keep_visible");
        EXPECT_EQ(std::count_if(keep.begin(), keep.end(), [](const PanelBox& box) { return box.name == "pig"; }), 3)
            << what;
        EXPECT_EQ(
            std::count_if(keep.begin(), keep.end(), [](const PanelBox& box) { return box.name == "landing point"; }), 1)
            << what;
        for (const PanelBox& thing : keep)
        {
            if (thing.name != "pig" && thing.name != "landing point")
                continue;
            for (const PanelBox& panel : boxes)
                EXPECT_TRUE(apart(panel, thing)) << what << ": the " << panel.name << " panel covers a " << thing.name;
        }
    }
}
} // namespace
} // namespace abalike::test
