#include "imgui/ImGuiInputQueue.hpp"

#include <algorithm>
#include <imgui.h>
#include <vector>

namespace abalike::app
{

void ImGuiInputQueue::push(const sf::Event& event)
{
    Item item;
    if (event.type == sf::Event::KeyPressed || event.type == sf::Event::KeyReleased)
    {
        if (event.key.code < 0 || event.key.code >= sf::Keyboard::KeyCount)
            return;
        item.key = event.key;
        item.down = event.type == sf::Event::KeyPressed;
    }
    else if (event.type == sf::Event::TextEntered)
    {
        // Control characters (Backspace, Enter, Tab, Delete) arrive as keys; only printable text goes in.
        if (event.text.unicode < 32 || event.text.unicode == 127)
            return;
        item.character = true;
        item.unicode = event.text.unicode;
    }
    else
        return;
    m_items.push_back(item);
}

void ImGuiInputQueue::drain(ImGuiIO& io)
{
    std::vector<sf::Keyboard::Key> changed;
    bool pressedThisFrame = false;
    bool afterPlainPress = false; ///< the item just taken was a key press without Ctrl, Alt or System
    while (!m_items.empty())
    {
        const Item& item = m_items.front();
        if (item.character)
        {
            // A character typed with its own key may share that key's frame; after any other key pressed in this
            // frame (Backspace, Ctrl+A, an arrow) it waits: ImGui would apply it before that key.
            if (pressedThisFrame && !afterPlainPress)
                break;
            io.AddInputCharacter(item.unicode);
            afterPlainPress = false;
        }
        else
        {
            if (std::find(changed.begin(), changed.end(), item.key.code) != changed.end())
                break; // its second transition in this frame: the next frame sees it
            changed.push_back(item.key.code);
            io.KeysDown[item.key.code] = item.down;
            io.KeyCtrl = item.key.control;
            io.KeyShift = item.key.shift;
            io.KeyAlt = item.key.alt;
            io.KeySuper = item.key.system;
            pressedThisFrame = pressedThisFrame || item.down;
            afterPlainPress = item.down && !item.key.control && !item.key.alt && !item.key.system;
        }
        m_items.pop_front();
    }
}

void ImGuiInputQueue::clear(ImGuiIO& io)
{
    m_items.clear();
    for (bool& key : io.KeysDown)
        key = false;
    io.KeyCtrl = io.KeyShift = io.KeyAlt = io.KeySuper = false;
}

} // namespace abalike::app
