#include "input/Gamepad.hpp"

#include <cmath>

namespace abalike::app
{

namespace
{
constexpr unsigned kButtonLb = 4;
} // namespace

sf::Keyboard::Key gamepadButtonKey(unsigned button)
{
    switch (button)
    {
    case 0:
        return sf::Keyboard::Space; // A
    case 1:
        return sf::Keyboard::Escape; // B
    case 2:
        return sf::Keyboard::R; // X
    case 3:
        return sf::Keyboard::T; // Y
    case kButtonLb:
        return sf::Keyboard::LShift;
    case 5:
        return sf::Keyboard::Home; // RB
    case 6:
        return sf::Keyboard::F1; // Back
    case 7:
        return sf::Keyboard::Escape; // Start
    default:
        return sf::Keyboard::Unknown;
    }
}

sf::Event GamepadTranslator::keyEvent(sf::Keyboard::Key key, bool pressed) const
{
    sf::Event event{};
    event.type = pressed ? sf::Event::KeyPressed : sf::Event::KeyReleased;
    event.key.code = key;
    event.key.alt = false;
    event.key.control = false;
    event.key.shift = m_coarse;
    event.key.system = false;
    return event;
}

GamepadTranslator::AxisKeys* GamepadTranslator::axisFor(sf::Joystick::Axis axis)
{
    switch (axis)
    {
    case sf::Joystick::X:
        return &m_axes[0];
    case sf::Joystick::Y:
        return &m_axes[1];
    case sf::Joystick::PovX:
        return &m_axes[2];
    case sf::Joystick::PovY:
        return &m_axes[3];
    case sf::Joystick::V:
        return &m_axes[4];
    default:
        return nullptr;
    }
}

void GamepadTranslator::moveAxis(AxisKeys& axis, float position, std::vector<sf::Event>& out)
{
    // Hysteresis: a held side stays held until the stick comes back under the release threshold.
    int side = axis.side;
    if (axis.side == 0 && std::abs(position) >= kPressThreshold)
        side = position < 0.0f ? -1 : 1;
    else if (axis.side != 0 && (std::abs(position) < kReleaseThreshold || (position < 0.0f) != (axis.side < 0)))
        side = std::abs(position) >= kPressThreshold ? (position < 0.0f ? -1 : 1) : 0;
    if (side == axis.side)
        return;
    if (axis.side != 0)
        out.push_back(keyEvent(axis.side < 0 ? axis.negative : axis.positive, false));
    axis.side = side;
    axis.heldS = 0.0;
    axis.nextRepeatS = kRepeatDelayS;
    if (side != 0)
        out.push_back(keyEvent(side < 0 ? axis.negative : axis.positive, true));
}

std::vector<sf::Event> GamepadTranslator::translate(const sf::Event& event)
{
    std::vector<sf::Event> out;
    switch (event.type)
    {
    case sf::Event::JoystickButtonPressed:
    case sf::Event::JoystickButtonReleased:
    {
        const bool pressed = event.type == sf::Event::JoystickButtonPressed;
        if (event.joystickButton.button == kButtonLb)
            m_coarse = pressed;
        if (const sf::Keyboard::Key key = gamepadButtonKey(event.joystickButton.button); key != sf::Keyboard::Unknown)
            out.push_back(keyEvent(key, pressed));
        break;
    }
    case sf::Event::JoystickMoved:
        if (AxisKeys* axis = axisFor(event.joystickMove.axis))
            moveAxis(*axis, event.joystickMove.position, out);
        break;
    case sf::Event::JoystickDisconnected:
        out = reset();
        break;
    default:
        break;
    }
    return out;
}

std::vector<sf::Event> GamepadTranslator::tick(double frameS)
{
    std::vector<sf::Event> out;
    for (AxisKeys& axis : m_axes)
    {
        if (axis.side == 0)
            continue;
        axis.heldS += frameS;
        while (axis.heldS >= axis.nextRepeatS)
        {
            out.push_back(keyEvent(axis.side < 0 ? axis.negative : axis.positive, true));
            axis.nextRepeatS += kRepeatIntervalS;
        }
    }
    return out;
}

std::vector<sf::Event> GamepadTranslator::reset()
{
    std::vector<sf::Event> out;
    for (AxisKeys& axis : m_axes)
        moveAxis(axis, 0.0f, out);
    if (m_coarse)
    {
        m_coarse = false;
        out.push_back(keyEvent(sf::Keyboard::LShift, false));
    }
    return out;
}

} // namespace abalike::app
