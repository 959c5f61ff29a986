#pragma once

#include "shell/ScreenStack.hpp"

#include <SFML/Window/Event.hpp>
#include <optional>
#include <vector>

namespace abalike::app
{

/// Where the player goes: the stack of screens, input a button posts as the key it stands for, and the end of the
/// run. The app applies the stack's changes and the posted input at the frame's edges.
class Navigator
{
public:
    ScreenStack& screens() { return m_screens; }
    const ScreenStack& screens() const { return m_screens; }
    /// Queues an input event to go through the same path as the player's at the start of the next frame: a toolbar
    /// button presses the key it stands for.
    void post(const sf::Event& event) { m_posted.push_back(event); }
    /// Ends the run after this frame with this exit code (the first code asked for wins).
    void quit(int exitCode = 0);

    /// The events posted since the last call (the app's frame loop).
    std::vector<sf::Event> takePosted();
    /// The exit code once quit() was called.
    const std::optional<int>& exitCode() const { return m_exitCode; }

private:
    ScreenStack m_screens;
    std::vector<sf::Event> m_posted;
    std::optional<int> m_exitCode;
};

} // namespace abalike::app
