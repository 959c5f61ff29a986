#pragma once

#include "shell/Screen.hpp"

#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/Texture.hpp>
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
    /// Draws like draw(), but what lies under the top screen is a copy of the window taken the first frame it was
    /// drawn: the screens under the top are not updated, so under a pause menu or a results card the whole scene
    /// costs one opaque copy instead of every layer again. Taken again after any change to the stack, the window's
    /// size or the settings (invalidateSnapshot()), and not used while a covered screen changesWhileCovered().
    void drawWithSnapshot(sf::RenderWindow& window);
    /// Forgets the copy: the next frame draws the covered screens again.
    void invalidateSnapshot() { m_snapshotValid = false; }
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
    std::unique_ptr<sf::Texture> m_snapshot; ///< made on first use: a texture needs a display, the stack does not
    bool m_snapshotValid = false;
};

} // namespace abalike::app
