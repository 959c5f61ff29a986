#pragma once

#include <SFML/Window/Event.hpp>
#include <array>
#include <vector>

namespace abalike::app
{

/// Turns a gamepad into the keyboard events the game already understands, so every screen works with a pad without
/// knowing about it (SFML's joystick API; any pad it reports, buttons in the Xbox layout SFML gives on Linux):
/// A = Space (launch, ability, confirm), B and Start = Escape (pause, back), X = R (restart), Y = T (teaching
/// overlay), Back = F1 (help), LB held = Shift (coarse aim steps), RB = Home (camera back to the level), the left
/// stick and the D-pad = the arrow keys, the right stick up / down = + / − (zoom). A direction held repeats like a
/// held key.
class GamepadTranslator
{
public:
    static constexpr float kPressThreshold = 50.0f;   ///< of SFML's ±100: a direction counts as pushed from here
    static constexpr float kReleaseThreshold = 30.0f; ///< and as let go below this (no chatter around one value)
    static constexpr double kRepeatDelayS = 0.35;
    static constexpr double kRepeatIntervalS = 0.08;

    /// The key events for one event; none for an event that is not a gamepad's or that maps to nothing.
    std::vector<sf::Event> translate(const sf::Event& event);
    /// Repeats for directions held long enough; call once a frame with the frame's duration.
    std::vector<sf::Event> tick(double frameS);
    /// Releases everything held (the pad was unplugged or the window lost focus).
    std::vector<sf::Event> reset();

private:
    /// A stick or hat axis seen as two keys (negative and positive side), with its repeat clock.
    struct AxisKeys
    {
        sf::Keyboard::Key negative = sf::Keyboard::Unknown;
        sf::Keyboard::Key positive = sf::Keyboard::Unknown;
        int side = 0; ///< -1, 0 or +1: which key is held
        double heldS = 0.0;
        double nextRepeatS = kRepeatDelayS;
    };

    sf::Event keyEvent(sf::Keyboard::Key key, bool pressed) const;
    void moveAxis(AxisKeys& axis, float position, std::vector<sf::Event>& out);
    AxisKeys* axisFor(sf::Joystick::Axis axis);

    std::array<AxisKeys, 5> m_axes{{
        {sf::Keyboard::Left, sf::Keyboard::Right},   // left stick X
        {sf::Keyboard::Up, sf::Keyboard::Down},      // left stick Y (SFML: up is negative)
        {sf::Keyboard::Left, sf::Keyboard::Right},   // D-pad X
        {sf::Keyboard::Up, sf::Keyboard::Down},      // D-pad Y (Linux: up is negative, as the stick)
        {sf::Keyboard::Add, sf::Keyboard::Subtract}, // right stick Y: up zooms in
    }};
    bool m_coarse = false; ///< LB held: arrows come with Shift
};

/// The key a gamepad button stands for (Unknown when the button has no use).
sf::Keyboard::Key gamepadButtonKey(unsigned button);

} // namespace abalike::app
