#pragma once

#include "screens/Screen.hpp"

#include <SFML/Graphics/RenderTarget.hpp>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace abalike::app
{

/// The screens of the game, top last. Changes asked for during a frame (push, pop, replace, clear) are queued and
/// applied in order by applyPending() after the frame, so a screen can ask for its own removal while it handles an
/// event and stays alive until that event is done.
class ScreenStack
{
public:
    /// Called for every applied change with "push", "pop" or "clear" and the screen's name.
    using Observer = std::function<void(std::string_view change, std::string_view screen)>;

    void push(std::unique_ptr<Screen> screen);
    void pop();
    /// Pops the top screen and pushes this one.
    void replace(std::unique_ptr<Screen> screen);
    /// Removes every screen (push after it to start over, e.g. back to the title).
    void clear();

    /// Applies the queued changes in the order they were asked for; returns true if anything changed.
    bool applyPending();
    bool hasPending() const { return !m_pending.empty(); }

    Screen* top() const { return m_screens.empty() ? nullptr : m_screens.back().get(); }
    bool empty() const { return m_screens.empty(); }
    std::size_t size() const { return m_screens.size(); }
    /// Names from bottom to top, e.g. {"title", "level-select", "play", "pause"}.
    std::vector<std::string> names() const;
    /// The screen just below the given one, or null.
    Screen* below(const Screen* screen) const;

    /// Draws from the topmost full screen up to the top.
    void draw(sf::RenderTarget& target) const;
    /// Tells every screen the window's new size.
    void resize(sf::Vector2u size);
    /// Every screen's finishBackgroundWork(), bottom first.
    void finishBackgroundWork();

    void setObserver(Observer observer) { m_observer = std::move(observer); }

private:
    enum class Change
    {
        Push,
        Pop,
        Clear,
    };
    struct Pending
    {
        Change change;
        std::unique_ptr<Screen> screen; ///< Push only
    };

    void notify(std::string_view change, const Screen& screen) const;

    std::vector<std::unique_ptr<Screen>> m_screens;
    std::vector<Pending> m_pending;
    Observer m_observer;
};

} // namespace abalike::app
