// No key loses a level (issue 57): on every screen, every key of the controls table and every ordered pair of them,
// one process per screen, checked through the trace. A screen may close only where the table says a key closes it:
// F1 and ? toggle the help and nothing else, the help closes on any key (as its card says), Esc goes back from a
// menu, P resumes from the pause menu, Enter and Space confirm a menu's choice, R restarts and N goes on from the
// results. A key that the table says leaves the screen is pressed last, alone: pressed first in a pair it would
// leave the screen the pair is meant for.
#include "../SanitizerBuild.hpp"
#include "RunGame.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <set>

namespace abalike::test
{
namespace
{

/// A key of the controls table as the script presses it.
struct TableKey
{
    std::string label; ///< as the table and the messages say it
    std::string name;  ///< SFML's name in the script
    bool shift = false;
    std::string text{}; ///< the text event the key types, if it is one the game reads ('?')
};

bool opensHelp(const TableKey& key)
{
    return key.label == "F1" || key.label == "?";
}

const std::vector<TableKey>& tableKeys()
{
    // Every key the controls table (src/app/input/Controls.cpp) names: aiming, flight, camera, playing, teaching,
    // anywhere, menus.
    static const std::vector<TableKey> keys{
        {"Up", "Up"},
        {"Down", "Down"},
        {"Right", "Right"},
        {"Left", "Left"},
        {"Space", "Space"},
        {"Enter", "Enter"},
        {"F", "F"},
        {"+", "Add"},
        {"-", "Subtract"},
        {"=", "Equal"},
        {"Hyphen", "Hyphen"},
        {"W", "W"},
        {"A", "A"},
        {"S", "S"},
        {"D", "D"},
        {"Home", "Home"},
        {"0", "Num0"},
        {"R", "R"},
        {"N", "N"},
        {"Esc", "Escape"},
        {"P", "P"},
        {"T", "T"},
        {"M", "M"},
        {",", "Comma"},
        {".", "Period"},
        {"L", "L"},
        {"C", "C"},
        {"V", "V"},
        {"Z", "Z"},
        {"E", "E"},
        {"G", "G"},
        {"I", "I"},
        {"[", "LBracket"},
        {"]", "RBracket"},
        {"K", "K"},
        {"F1", "F1"},
        {"?", "Slash", true, "?"},
        {"Tab", "Tab"},
    };
    return keys;
}

/// The script events of one key stroke in one frame: press, its text, release.
std::string stroke(const TableKey& key, int frame)
{
    const std::string at = R"({"frame": )" + std::to_string(frame) + R"(, "key": ")" + key.name + "\"" +
                           (key.shift ? R"(, "shift": true)" : "");
    std::string out = at + R"(, "action": "press"}, )";
    if (!key.text.empty())
        out += R"({"frame": )" + std::to_string(frame) + R"(, "text": ")" + key.text + "\"}, ";
    return out + at + R"(, "action": "release"})";
}

/// A screen to press every key on, how to get there, and what the table lets its keys close.
struct ScreenCase
{
    std::string screen;             ///< the screen under test, on top when the keys start
    std::string command;            ///< "play ..." or "edit ..."
    std::string opening;            ///< script events (JSON objects, comma-separated) that open it
    int firstFrame = 10;            ///< the first key's frame
    std::vector<std::string> stack; ///< the stack the keys start on, bottom first
    std::set<std::string> leaving;  ///< keys the table says leave this screen: pressed last, alone
    std::string size = "640x360";   ///< a small window: the frames are cheap
    /// The help closes on any key: after each pair F1 opens it again (unless the pair's second key did).
    bool reopenHelp = false;
};

/// gtest prints a case by its screen, not its bytes.
void PrintTo(const ScreenCase& test, std::ostream* out)
{
    *out << test.screen;
}

std::string caseName(const ::testing::TestParamInfo<ScreenCase>& info)
{
    std::string name = info.param.screen;
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

const std::set<std::string> kMenus{"title", "level-select", "pause", "results", "settings", "lesson-select", "learn"};

/// Whether the table lets this key, pressed with `top` on top of the stack, close `closed`.
bool tableLetsClose(const std::string& top, const std::string& key, const std::string& closed)
{
    if (key == "F1" || key == "?")
        return closed == "help"; // "This help: F1 or ?" toggles it and nothing else
    if (top == "help")
        return closed == "help"; // the help closes on any key, and only itself
    if (key == "Esc")
        return closed == top && top != "play"; // Menus: Back (on a level, Esc opens the pause menu)
    if (key == "P")
        return top == "pause" && closed == "pause"; // the pause menu's own key resumes
    if (key == "Enter" || key == "Space")
        return kMenus.count(top) != 0; // Menus: Confirm, whatever the choice does
    if (key == "R")
        return (top == "play" || top == "pause" || top == "results") &&
               (closed == "play" || closed == "pause" || closed == "results"); // Restart the level
    if (key == "N")
        return top == "results" && (closed == "results" || closed == "play"); // Next level (after a win)
    return false;
}

class KeyPairs : public ::testing::TestWithParam<ScreenCase>
{
protected:
    KeyPairs() : m_dir(std::string("keypairs-") + GetParam().screen)
    {
        std::filesystem::create_directories(m_dir.path() / "data");
    }
    ScratchDir m_dir;
};

TEST_P(KeyPairs, NoKeyNorPairOfKeysClosesAScreenTheTableDoesNotSayCloses)
{
    const ScreenCase& test = GetParam();
    // Under the sanitizers (an -O0 build, several times slower) the play screen's pairs only: the same code, and the
    // F1/? toggles over a level that lost it once; the whole set would take minutes there.
    if (kSanitizerBuild && test.screen != "play")
        GTEST_SKIP() << "the sanitizer build presses the pairs on the play screen only";
    std::vector<const TableKey*> pressed;
    std::vector<const TableKey*> last;
    for (const TableKey& key : tableKeys())
        (test.leaving.count(key.label) != 0 ? last : pressed).push_back(&key);

    // Every ordered pair of the keys that keep the screen, a frame apart, then each leaving key alone.
    std::map<int, std::string> keyAt;
    std::string events = test.opening;
    int frame = test.firstFrame;
    const auto press = [&](const TableKey& key)
    {
        events += (events.empty() ? "" : ", ") + stroke(key, frame);
        keyAt[frame] = key.label;
        ++frame;
    };
    const TableKey& f1 =
        *std::find_if(tableKeys().begin(), tableKeys().end(), [](const TableKey& key) { return key.label == "F1"; });
    std::vector<int> pairFrames; // each pair's first frame
    for (const TableKey* first : pressed)
        for (const TableKey* second : pressed)
        {
            pairFrames.push_back(frame);
            press(*first);
            press(*second);
            if (test.reopenHelp && !opensHelp(*second))
                press(f1);
            else if (!test.reopenHelp && !opensHelp(*first) && opensHelp(*second))
                press(f1); // the help the pair opened: closed again, so the next pair starts on the screen
        }
    const int pairsEnd = frame;
    for (const TableKey* key : last)
    {
        press(*key);
        frame += 2; // one at a time
    }
    const std::string scriptPath = m_dir.write("script.json", "[" + events + "]");
    const GameRun run = runGame(test.command + " --size " + test.size + " --frames " + std::to_string(frame + 2) +
                                    " --script '" + scriptPath + "'",
                                m_dir.path() / "data");
    ASSERT_EQ(run.exitCode, 0) << run.err;

    // Replay the stack from the trace. A key is handled by the screen on top when its frame began (the stack changes
    // a frame asks for are applied after it).
    std::vector<std::string> stack;
    std::map<int, std::string> topAt;
    int lastFrame = -1;
    int wrongCloses = 0;
    std::vector<std::string> stackAtPairsEnd;
    for (const nlohmann::json& line : run.trace)
    {
        const int at = line.value("frame", 0);
        if (at != lastFrame)
        {
            for (int f = lastFrame + 1; f <= at; ++f)
            {
                topAt[f] = stack.empty() ? "" : stack.back();
                if (f == pairsEnd)
                    stackAtPairsEnd = stack;
            }
            lastFrame = at;
        }
        const std::string event = line.value("event", "");
        if (event == "push")
            stack.push_back(line.value("screen", ""));
        else if (event == "pop" || event == "clear")
        {
            const std::vector<std::string> closed =
                event == "pop" ? std::vector<std::string>{line.value("screen", "")} : stack;
            for (const std::string& screen : closed)
            {
                const auto key = keyAt.find(at);
                const bool allowed =
                    at < test.firstFrame || (key != keyAt.end() && tableLetsClose(topAt[at], key->second, screen));
                if (!allowed && ++wrongCloses <= 10)
                    ADD_FAILURE() << "frame " << at << ": " << (key != keyAt.end() ? key->second : "no key") << " on "
                                  << topAt[at] << " closed " << screen;
            }
            if (event == "pop" && !stack.empty())
                stack.pop_back();
            else if (event == "clear")
                stack.clear();
        }
    }
    EXPECT_EQ(wrongCloses, 0);
    const std::vector<std::string> exitFrame = run.values("exit", "frame");
    ASSERT_EQ(exitFrame.size(), 1u);
    EXPECT_GE(std::stoi(exitFrame.front()), pairsEnd) << "the run went on past the pairs";

    // The pairs were pressed on the screen under test: the first key of every pair found it on top, or the help
    // that F1 or ? and a page key of the help (Right, Tab) left open over it.
    std::size_t onScreen = 0;
    for (const int first : pairFrames)
        onScreen += topAt.count(first) != 0 && (topAt[first] == test.screen || topAt[first] == "help") ? 1 : 0;
    EXPECT_EQ(onScreen, pairFrames.size())
        << onScreen << " of " << pairFrames.size() << " pairs began on " << test.screen;
    if (lastFrame < pairsEnd)
        stackAtPairsEnd = stack;
    std::vector<std::string> withHelp = test.stack;
    withHelp.push_back("help");
    EXPECT_TRUE(stackAtPairsEnd == test.stack || stackAtPairsEnd == withHelp)
        << "after the pairs the stack is " << ::testing::PrintToString(stackAtPairsEnd);
}

const std::string kLevel = sourceFile("levels/1-1-first-flight.json");

INSTANTIATE_TEST_SUITE_P(
    EveryScreen, KeyPairs,
    ::testing::Values(
        // A level being aimed at: launching is left out of the pairs (it would end the level in results).
        ScreenCase{"play", "play " + kLevel, "", 10, {"play"}, {"Esc", "P", "Space", "Enter"}},
        // The help over a level: its first key closes it, the second reaches the level, F1 opens it again.
        ScreenCase{"help",
                   "play " + kLevel,
                   R"({"frame": 3, "key": "F1"})",
                   10,
                   {"play", "help"},
                   {"Esc", "P", "Space", "Enter"},
                   "1280x720",
                   true},
        ScreenCase{"pause",
                   "play " + kLevel,
                   R"({"frame": 3, "key": "Escape"})",
                   10,
                   {"play", "pause"},
                   {"Esc", "P", "Space", "Enter", "R"}},
        // 3-1's reference shot wins it; the results open at frame 301 and take keys half a second later.
        ScreenCase{"results",
                   "play " + sourceFile("levels/3-1-tailwind.json") + " --shot 30,30",
                   "",
                   340,
                   {"play", "results"},
                   {"Esc", "Space", "Enter", "R", "N"}},
        ScreenCase{"level-select",
                   "play",
                   R"({"frame": 2, "key": "Down"}, {"frame": 3, "key": "Enter"})",
                   10,
                   {"title", "level-select"},
                   {"Esc", "Space", "Enter", "E"}}, // E: the editor on the level
        ScreenCase{"title", "play", "", 10, {"title"}, {"Esc", "Space", "Enter"}},
        // Settings: the sixth entry of the title menu.
        ScreenCase{"settings",
                   "play",
                   R"({"frame": 2, "key": "Down"}, {"frame": 3, "key": "Down"}, {"frame": 4, "key": "Down"},
                      {"frame": 5, "key": "Down"}, {"frame": 6, "key": "Down"}, {"frame": 7, "key": "Enter"})",
                   12,
                   {"title", "settings"},
                   {"Esc", "Space", "Enter"}},
        ScreenCase{"editor", "edit " + kLevel, "", 10, {"editor"}, {"Esc"}}),
    caseName);

} // namespace
} // namespace abalike::test
