#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace abalike
{

/// One timed input event of a scripted run (`abalike play --script INPUT.json`). The core knows events only by
/// name; the app turns them into window events and feeds them through the same path as real input.
struct ScriptEvent
{
    enum class Kind
    {
        Key,   ///< a keyboard key
        Mouse, ///< a mouse button or the pointer moving
        Wheel, ///< the mouse wheel
        Text,  ///< typed text, one character event each
    };
    enum class Action
    {
        Tap,     ///< a key press followed by its release in the same frame
        Press,   ///< key or button goes down (and stays down until a Release)
        Release, ///< key or button goes up
        Move,    ///< the pointer moves to (x, y)
    };

    int frame = 1; ///< frames count from 1; the event is applied at the start of its frame
    Kind kind = Kind::Key;
    Action action = Action::Tap;
    std::string key; ///< Kind::Key: the window library's key name, e.g. "Escape", "Space", "F1", "Add"
    bool shift = false;
    bool ctrl = false;
    bool alt = false;
    std::string button; ///< Kind::Mouse: "left", "right" or "middle" (empty for Move)
    int x = 0;          ///< Kind::Mouse, Kind::Wheel: window pixel coordinates
    int y = 0;
    int wheelDelta = 0;  ///< Kind::Wheel: positive = up
    std::string text;    ///< Kind::Text: UTF-8
    std::string pointer; ///< JSON pointer of the event in its file, for messages
};

/// What a script may refer to: the key names the window library knows and the window size in pixels.
struct InputScriptRules
{
    std::function<bool(std::string_view)> isKeyName;
    std::vector<std::string> keyNames; ///< for "did you mean" suggestions
    unsigned width = 1280;
    unsigned height = 720;
};

/// The events of a script, ordered by frame (events of one frame keep their order in the file).
struct InputScript
{
    std::vector<ScriptEvent> events;
    /// The last frame any event is applied in (0 for an empty script).
    int lastFrame() const { return events.empty() ? 0 : events.back().frame; }
};

/// Parses a script: a JSON array of events such as {"frame": 30, "key": "Down"}, {"frame": 40, "mouse": "press",
/// "button": "left", "x": 640, "y": 360}, {"frame": 50, "wheel": 1, "x": 640, "y": 360}, {"frame": 60, "text": "ab"}.
/// Throws LevelLoadError with every problem located as FILE:LINE:COL.
InputScript parseInputScript(std::string_view text, const std::string& fileName, const InputScriptRules& rules);

/// Reads and parses a script file. Throws LevelLoadError.
InputScript loadInputScript(const std::string& path, const InputScriptRules& rules);

} // namespace abalike
