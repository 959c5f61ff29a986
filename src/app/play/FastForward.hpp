#pragma once

#include <SFML/Window/Event.hpp>

namespace abalike::app
{

/// Holding F plays the bird's free flight (before it touches anything) at 3x: three fixed physics steps per tick
/// instead of one. The physics is unchanged (the same steps, the same results, the same trace); only the pace it is
/// shown at. It ends by itself at the first contact, where the structure's fall is worth watching at real time.
class FastForward
{
public:
    static constexpr int kSpeedUp = 3;

    /// Follows F's presses and releases (and drops it when the window loses focus). Returns true for F.
    bool handleEvent(const sf::Event& event)
    {
        if ((event.type == sf::Event::KeyPressed || event.type == sf::Event::KeyReleased) &&
            event.key.code == sf::Keyboard::F)
        {
            m_held = event.type == sf::Event::KeyPressed;
            return true;
        }
        if (event.type == sf::Event::LostFocus)
            m_held = false;
        return false;
    }

    /// Physics steps for this tick at most: kSpeedUp while F is held at real-time pace, else 1. The caller stops
    /// early at the first contact.
    int stepsPerTick(int slowMotionDivisor) const { return m_held && slowMotionDivisor == 1 ? kSpeedUp : 1; }

    bool held() const { return m_held; }

private:
    bool m_held = false;
};

} // namespace abalike::app
