#pragma once

#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Window/Event.hpp>
#include <string_view>

namespace abalike::app
{

/// One screen of the game (title, level select, play, pause, ...). Screens live on the App's ScreenStack: only
/// the top one gets input and updates; drawing starts at the topmost screen that is not an overlay, so an
/// overlay (pause, help, results) is drawn over the screen it covers, which stands still under it.
class Screen
{
public:
    virtual ~Screen() = default;

    /// Short, stable name for traces and tests ("title", "level-select", "play", "pause", ...).
    virtual std::string_view name() const = 0;
    /// Drawn over the screen below it instead of hiding it.
    virtual bool isOverlay() const { return false; }
    /// True while the screen takes typed text (a text field has focus): the app then leaves '?' and other
    /// printable keys to it instead of treating them as shortcuts.
    virtual bool wantsTextInput() const { return false; }

    /// A window event, real or scripted (they arrive the same way). Top screen only.
    virtual void handleEvent(const sf::Event& event) = 0;
    /// One fixed physics step of dtS seconds. Top screen only, so an overlay pauses what is under it.
    virtual void fixedUpdate(double dtS) { (void)dtS; }
    /// Once per drawn frame, before drawing, with the time since the last frame (animation, camera). Top only.
    virtual void frameUpdate(double frameS) { (void)frameS; }
    /// Draws the screen in window pixels (the window's view maps one unit to one pixel).
    virtual void draw(sf::RenderTarget& target) = 0;

    /// The window has a new size. Every screen on the stack is told.
    virtual void onResize(sf::Vector2u size) { (void)size; }
    /// The screen is on top again after the one above it left.
    virtual void onResume() {}
    /// True while the screen's picture changes even when another screen covers it (only the top screen is
    /// updated, so most screens look the same under an overlay; ScreenStack::drawWithSnapshot relies on it).
    virtual bool changesWhileCovered() const { return false; }
    /// Waits for work the screen started in the background, so that a scripted run's last frame shows its result.
    virtual void finishBackgroundWork() {}
    /// The window's close button was pressed while this screen is on top. Return true to handle it yourself (the
    /// editor asks to save unsaved changes first, then quits); false lets the app quit at once.
    virtual bool onCloseRequest() { return false; }
    /// Whether a right click means "back" (Escape) here, the mouse's way back out of every menu. Screens that use
    /// the right button themselves (play: the tape measure; the editor) say no.
    virtual bool rightClickIsBack() const { return true; }
};

/// The help screen's name: the app opens and closes it with F1 and '?' over any screen (AppOptions::helpScreen).
inline constexpr std::string_view kHelpScreenName = "help";

} // namespace abalike::app
