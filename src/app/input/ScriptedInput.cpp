#include "input/ScriptedInput.hpp"

#include "input/KeyNames.hpp"

#include <SFML/System/String.hpp>

namespace abalike::app
{

InputScriptRules scriptRules(unsigned width, unsigned height)
{
    InputScriptRules rules;
    rules.isKeyName = [](std::string_view name)
    {
        return keyFromName(name).has_value();
    };
    rules.keyNames = allKeyNames();
    rules.width = width;
    rules.height = height;
    return rules;
}

InputScript loadScript(const std::string& path, unsigned width, unsigned height)
{
    return loadInputScript(path, scriptRules(width, height));
}

std::vector<sf::Event> ScriptedInput::eventsForFrame(int frame)
{
    std::vector<sf::Event> events;
    while (m_next < m_script.events.size() && m_script.events[m_next].frame <= frame)
    {
        const std::vector<sf::Event> some = toWindowEvents(m_script.events[m_next++]);
        events.insert(events.end(), some.begin(), some.end());
    }
    return events;
}

std::vector<sf::Event> toWindowEvents(const ScriptEvent& script)
{
    std::vector<sf::Event> events;
    sf::Event event{};
    switch (script.kind)
    {
    case ScriptEvent::Kind::Key:
    {
        event.key.code = keyFromName(script.key).value_or(sf::Keyboard::Unknown);
        event.key.shift = script.shift;
        event.key.control = script.ctrl;
        event.key.alt = script.alt;
        event.key.system = false;
        if (script.action != ScriptEvent::Action::Release)
        {
            event.type = sf::Event::KeyPressed;
            events.push_back(event);
        }
        if (script.action != ScriptEvent::Action::Press)
        {
            event.type = sf::Event::KeyReleased;
            events.push_back(event);
            // As a keyboard does, Ctrl and Alt come up after the key: the next event sees them up (an ImGui text
            // field ignores typed characters while Ctrl reads as held). Shift stays as the script holds it.
            const std::pair<bool, sf::Keyboard::Key> modifiers[] = {{script.ctrl, sf::Keyboard::LControl},
                                                                    {script.alt, sf::Keyboard::LAlt}};
            for (const auto& [held, key] : modifiers)
            {
                if (!held)
                    continue;
                sf::Event up{};
                up.type = sf::Event::KeyReleased;
                up.key.code = key;
                events.push_back(up);
            }
        }
        break;
    }
    case ScriptEvent::Kind::Mouse:
        if (script.action == ScriptEvent::Action::Move)
        {
            event.type = sf::Event::MouseMoved;
            event.mouseMove = {script.x, script.y};
        }
        else
        {
            event.type = script.action == ScriptEvent::Action::Press ? sf::Event::MouseButtonPressed
                                                                     : sf::Event::MouseButtonReleased;
            event.mouseButton.button = script.button == "right"    ? sf::Mouse::Right
                                       : script.button == "middle" ? sf::Mouse::Middle
                                                                   : sf::Mouse::Left;
            event.mouseButton.x = script.x;
            event.mouseButton.y = script.y;
        }
        events.push_back(event);
        break;
    case ScriptEvent::Kind::Wheel:
        event.type = sf::Event::MouseWheelScrolled;
        event.mouseWheelScroll.wheel = sf::Mouse::VerticalWheel;
        event.mouseWheelScroll.delta = static_cast<float>(script.wheelDelta);
        event.mouseWheelScroll.x = script.x;
        event.mouseWheelScroll.y = script.y;
        events.push_back(event);
        break;
    case ScriptEvent::Kind::Text:
    {
        const sf::String text = sf::String::fromUtf8(script.text.begin(), script.text.end());
        event.type = sf::Event::TextEntered;
        for (const sf::Uint32 c : text)
        {
            event.text.unicode = c;
            events.push_back(event);
        }
        break;
    }
    }
    return events;
}

} // namespace abalike::app
