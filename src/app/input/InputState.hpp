#pragma once

#include <SFML/System/Vector2.hpp>
#include <SFML/Window/Event.hpp>
#include <SFML/Window/Keyboard.hpp>
#include <SFML/Window/Mouse.hpp>
#include <array>

namespace abalike::app
{

/// What is held down and where the pointer is, as told by the events the game received (real or scripted).
/// Screens ask this instead of sf::Keyboard / sf::Mouse, so a scripted run holds keys exactly as a player would.
class InputState
{
public:
    /// Updates from one event; call for every event before it is dispatched.
    void apply(const sf::Event& event);
    /// Forgets everything held (the window lost focus: releases will not arrive).
    void releaseAll();

    bool keyDown(sf::Keyboard::Key key) const;
    bool buttonDown(sf::Mouse::Button button) const;
    bool shift() const { return keyDown(sf::Keyboard::LShift) || keyDown(sf::Keyboard::RShift); }
    bool ctrl() const { return keyDown(sf::Keyboard::LControl) || keyDown(sf::Keyboard::RControl); }
    /// True when the last key press came from holding the key down (the system's key repeat), not a new press.
    bool lastPressRepeated() const { return m_lastPressRepeated; }
    /// Last known pointer position in window pixels.
    sf::Vector2i pointer() const { return m_pointer; }

private:
    std::array<bool, sf::Keyboard::KeyCount> m_keys{};
    std::array<bool, sf::Mouse::ButtonCount> m_buttons{};
    sf::Vector2i m_pointer{0, 0};
    bool m_lastPressRepeated = false;
};

} // namespace abalike::app
