#include <abalike/level/LevelIO.hpp>
#include <abalike/script/InputScript.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace abalike
{
namespace
{

InputScriptRules rules()
{
    InputScriptRules r;
    r.keyNames = {"Escape", "Space", "Down", "Up", "F1", "Add", "A", "Enter", "LShift"};
    r.isKeyName = [names = r.keyNames](std::string_view name)
    {
        return std::find(names.begin(), names.end(), name) != names.end();
    };
    r.width = 1280;
    r.height = 720;
    return r;
}

/// The problems of a script that does not parse, as FILE:LINE:COL lines.
std::vector<std::string> problems(const std::string& text)
{
    try
    {
        parseInputScript(text, "script.json", rules());
    }
    catch (const LevelLoadError& error)
    {
        std::vector<std::string> lines;
        for (const LevelIssue& issue : error.issues())
            lines.push_back(issue.format());
        return lines;
    }
    return {};
}

TEST(InputScript, ReadsEveryKindOfEvent)
{
    const InputScript script = parseInputScript(R"([
        {"frame": 30, "key": "Down"},
        {"frame": 31, "key": "Space", "shift": true, "action": "press"},
        {"frame": 32, "key": "Space", "action": "release"},
        {"frame": 40, "mouse": "press", "button": "left", "x": 640, "y": 360},
        {"frame": 41, "mouse": "move", "x": 600, "y": 380},
        {"frame": 42, "mouse": "release", "button": "right", "x": 600, "y": 380},
        {"frame": 50, "wheel": -2, "x": 10, "y": 20},
        {"frame": 60, "text": "a\u00e9?"}
    ])",
                                                "s.json", rules());
    ASSERT_EQ(script.events.size(), 8u);
    const ScriptEvent& tap = script.events[0];
    EXPECT_EQ(tap.frame, 30);
    EXPECT_EQ(tap.kind, ScriptEvent::Kind::Key);
    EXPECT_EQ(tap.action, ScriptEvent::Action::Tap);
    EXPECT_EQ(tap.key, "Down");
    EXPECT_FALSE(tap.shift);
    EXPECT_EQ(script.events[1].action, ScriptEvent::Action::Press);
    EXPECT_TRUE(script.events[1].shift);
    EXPECT_EQ(script.events[2].action, ScriptEvent::Action::Release);
    const ScriptEvent& press = script.events[3];
    EXPECT_EQ(press.kind, ScriptEvent::Kind::Mouse);
    EXPECT_EQ(press.action, ScriptEvent::Action::Press);
    EXPECT_EQ(press.button, "left");
    EXPECT_EQ(press.x, 640);
    EXPECT_EQ(press.y, 360);
    EXPECT_EQ(script.events[4].action, ScriptEvent::Action::Move);
    EXPECT_EQ(script.events[5].button, "right");
    EXPECT_EQ(script.events[6].kind, ScriptEvent::Kind::Wheel);
    EXPECT_EQ(script.events[6].wheelDelta, -2);
    EXPECT_EQ(script.events[7].text, "a\xC3\xA9?");
    EXPECT_EQ(script.lastFrame(), 60);
}

TEST(InputScript, EventsAreOrderedByFrameKeepingFileOrderWithinAFrame)
{
    const InputScript script = parseInputScript(
        R"([{"frame": 9, "key": "A"}, {"frame": 2, "key": "Up"}, {"frame": 9, "key": "Down"}, {"frame": 2, "key": "F1"}])",
        "s.json", rules());
    std::vector<std::string> keys;
    for (const ScriptEvent& e : script.events)
        keys.push_back(std::to_string(e.frame) + e.key);
    EXPECT_EQ(keys, (std::vector<std::string>{"2Up", "2F1", "9A", "9Down"}));
}

TEST(InputScript, AnEmptyScriptIsValid)
{
    EXPECT_TRUE(parseInputScript("[]", "s.json", rules()).events.empty());
}

TEST(InputScript, EveryProblemIsLocated)
{
    const std::vector<std::string> found = problems(R"([
  {"frame": 0, "key": "Down"},
  {"frame": 3, "key": "Escpe"},
  {"frame": 4, "mouse": "press", "x": 1280, "y": 10},
  {"frame": 5, "key": "Up", "mouse": "move"},
  {"frame": 6, "wheel": 0, "x": 1, "y": 1},
  {"key": "Up"},
  {"frame": 7.5, "text": ""},
  {"frame": 8, "mouse": "move", "button": "left", "x": 1, "y": 1},
  {"frame": 9, "key": "Up", "action": "hold"},
  {"frame": 10, "key": "Up", "colour": "red"},
  {"frame": 11, "key": "Up", "x": 3}
])");
    const std::vector<std::string> expected{
        "script.json:2:13: error: /0/frame: expected a whole number from 1 to 1000000, got 0",
        "script.json:3:23: error: /1/key: unknown key name \"Escpe\" (did you mean \"Escape\"?)",
        "script.json:4:39: error: /2/x: expected a whole number from 0 to 1279 (window pixels of the 1280x720 window), "
        "got 1280",
        "script.json:5:3: error: /3: an event has exactly one of \"key\", \"mouse\", \"wheel\" or \"text\" (split it "
        "into several events)",
        "script.json:6:25: error: /4/wheel: a wheel event turns the wheel (expected a non-zero whole number)",
        "script.json:7:3: error: /5: missing required key \"frame\" (expected a whole number)",
        "script.json:8:13: error: /6/frame: expected a whole number from 1 to 1000000, got 7.5",
        "script.json:8:26: error: /6/text: expected a non-empty string, got the string \"\"",
        "script.json:9:34: error: /7/button: a pointer move has no button",
        "script.json:10:39: error: /8/action: expected \"tap\", \"press\" or \"release\", got the string \"hold\"",
        "script.json:11:31: error: /9/colour: unknown key \"colour\" (expected one of: frame key action shift ctrl alt "
        "mouse button x y wheel text)",
        "script.json:12:31: error: /10/x: \"x\" does not belong to a key event",
    };
    EXPECT_EQ(found, expected);
}

TEST(InputScript, SyntaxAndShapeErrorsAreLocatedToo)
{
    const std::vector<std::string> syntax =
        problems("[{\"frame\": 1, \"key\": \"Up\"},\n {\"frame\": 2 \"key\": \"Up\"}]");
    ASSERT_EQ(syntax.size(), 1u);
    EXPECT_EQ(syntax[0].rfind("script.json:2:", 0), 0u) << syntax[0];
    const std::vector<std::string> notArray = problems(R"({"frame": 1, "key": "Up"})");
    ASSERT_EQ(notArray.size(), 1u);
    EXPECT_NE(notArray[0].find("expected an array of events, got an object"), std::string::npos) << notArray[0];
    const std::vector<std::string> duplicate = problems(R"([{"frame": 1, "frame": 2, "key": "Up"}])");
    ASSERT_FALSE(duplicate.empty());
    EXPECT_NE(duplicate[0].find("duplicate key \"frame\""), std::string::npos) << duplicate[0];
}

TEST(InputScript, AMissingFileIsAClearError)
{
    try
    {
        loadInputScript("/nonexistent/script.json", rules());
        FAIL() << "expected an error";
    }
    catch (const LevelLoadError& error)
    {
        ASSERT_EQ(error.issues().size(), 1u);
        EXPECT_NE(error.issues()[0].format().find("cannot open file"), std::string::npos);
    }
}

} // namespace
} // namespace abalike
