#pragma once

#include <SFML/Window/Event.hpp>
#include <deque>

struct ImGuiIO;

namespace abalike::app
{

/// Keys and typed characters for Dear ImGui 1.86, which reads key state once per frame (io.KeysDown; the input
/// queue came in 1.87): a key pressed and released between two frames would never be seen down, so 20 quick
/// Backspaces deleted one character. SFML's events wait here in order and each frame takes what it can see
/// apart: at most one transition per key, and no character after an editing key in the same frame (ImGui handles a
/// frame's characters before its keys). What is left drains over the next frames.
class ImGuiInputQueue
{
public:
    /// Keeps a key press or release, or a printable character; other events are not its business.
    void push(const sf::Event& event);
    /// Moves what this frame can take into io (before ImGui::NewFrame).
    void drain(ImGuiIO& io);
    /// Focus lost: nothing waiting and nothing held.
    void clear(ImGuiIO& io);

    bool empty() const { return m_items.empty(); }

private:
    struct Item
    {
        bool character = false;
        unsigned unicode = 0;    ///< a character
        sf::Event::KeyEvent key; ///< a key's transition
        bool down = false;
    };
    std::deque<Item> m_items;
};

} // namespace abalike::app
