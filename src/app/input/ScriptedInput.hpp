#pragma once

#include <SFML/Window/Event.hpp>
#include <abalike/script/InputScript.hpp>
#include <cstddef>
#include <string>
#include <vector>

namespace abalike::app
{

/// The rules a script is checked against: SFML's key names and the window size.
InputScriptRules scriptRules(unsigned width, unsigned height);

/// Reads `--script INPUT.json`. Throws LevelLoadError with located problems.
InputScript loadScript(const std::string& path, unsigned width, unsigned height);

/// Plays a script back as window events, frame by frame.
class ScriptedInput
{
public:
    explicit ScriptedInput(InputScript script = {}) : m_script(std::move(script)) {}

    /// The window events of this frame (frames count from 1), in script order; each frame is asked for once,
    /// in increasing order.
    std::vector<sf::Event> eventsForFrame(int frame);
    /// True once every event has been handed out.
    bool finished() const { return m_next >= m_script.events.size(); }
    int lastFrame() const { return m_script.lastFrame(); }

private:
    InputScript m_script;
    std::size_t m_next = 0;
};

/// The window events one script event stands for (a key tap is a press and a release; text is one event per
/// character).
std::vector<sf::Event> toWindowEvents(const ScriptEvent& event);

} // namespace abalike::app
