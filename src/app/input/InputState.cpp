#include "input/InputState.hpp"

namespace abalike::app
{

void InputState::apply(const sf::Event& event)
{
    switch (event.type)
    {
    case sf::Event::KeyPressed:
    case sf::Event::KeyReleased:
        if (event.key.code >= 0 && event.key.code < sf::Keyboard::KeyCount)
        {
            const auto index = static_cast<std::size_t>(event.key.code);
            if (event.type == sf::Event::KeyPressed)
                m_lastPressRepeated = m_keys[index];
            m_keys[index] = event.type == sf::Event::KeyPressed;
        }
        break;
    case sf::Event::MouseButtonPressed:
    case sf::Event::MouseButtonReleased:
        if (event.mouseButton.button >= 0 && event.mouseButton.button < sf::Mouse::ButtonCount)
            m_buttons[static_cast<std::size_t>(event.mouseButton.button)] = event.type == sf::Event::MouseButtonPressed;
        m_pointer = {event.mouseButton.x, event.mouseButton.y};
        break;
    case sf::Event::MouseMoved:
        m_pointer = {event.mouseMove.x, event.mouseMove.y};
        break;
    case sf::Event::MouseWheelScrolled:
        m_pointer = {event.mouseWheelScroll.x, event.mouseWheelScroll.y};
        break;
    case sf::Event::LostFocus:
        releaseAll();
        break;
    default:
        break;
    }
}

void InputState::releaseAll()
{
    m_keys.fill(false);
    m_buttons.fill(false);
}

bool InputState::keyDown(sf::Keyboard::Key key) const
{
    return key >= 0 && key < sf::Keyboard::KeyCount && m_keys[static_cast<std::size_t>(key)];
}

bool InputState::buttonDown(sf::Mouse::Button button) const
{
    return button >= 0 && button < sf::Mouse::ButtonCount && m_buttons[static_cast<std::size_t>(button)];
}

} // namespace abalike::app
