#include "FuzzInput.hpp"

#include <abalike/level/LevelIO.hpp>
#include <abalike/script/InputScript.hpp>

#include <algorithm>

/// The input-script parser (`abalike play --script`) must answer any bytes with a script or a LevelLoadError, and
/// every event of a script it accepts must be inside the rules it was given.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace abalike;
    static const InputScriptRules rules = []
    {
        InputScriptRules r;
        r.keyNames = {"Escape", "Space", "Enter", "Up", "Down", "Left", "Right", "F1", "Add", "A", "LShift"};
        r.isKeyName = [names = r.keyNames](std::string_view name)
        {
            return std::find(names.begin(), names.end(), name) != names.end();
        };
        r.width = 640;
        r.height = 480;
        return r;
    }();
    InputScript script;
    try
    {
        script = parseInputScript(fuzz::asText(data, size), "fuzz.json", rules);
    }
    catch (const LevelLoadError& e)
    {
        if (e.issues().empty())
            fuzz::fail("LevelLoadError without an issue");
        return 0;
    }
    int lastFrame = 0;
    for (const ScriptEvent& event : script.events)
    {
        if (event.frame < 1 || event.frame < lastFrame)
            fuzz::fail("events out of frame order");
        lastFrame = event.frame;
        if (event.x < 0 || event.x >= 640 || event.y < 0 || event.y >= 480)
            fuzz::fail("a position outside the window was accepted");
        if (event.kind == ScriptEvent::Kind::Key && !rules.isKeyName(event.key))
            fuzz::fail("an unknown key name was accepted");
    }
    return 0;
}
