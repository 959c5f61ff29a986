// Keys and characters reach Dear ImGui 1.86 one frame-visible transition at a time (imgui/ImGuiInputQueue.hpp).
#include "imgui/ImGuiInputQueue.hpp"

#include <gtest/gtest.h>
#include <imgui.h>
#include <string>

namespace abalike::app
{
namespace
{

sf::Event keyEvent(sf::Keyboard::Key code, bool down, bool control = false)
{
    sf::Event event{};
    event.type = down ? sf::Event::KeyPressed : sf::Event::KeyReleased;
    event.key.code = code;
    event.key.control = control;
    return event;
}

sf::Event textEvent(char c)
{
    sf::Event event{};
    event.type = sf::Event::TextEntered;
    event.text.unicode = static_cast<sf::Uint32>(c);
    return event;
}

/// What one frame of ImGui would see: the characters added and the keys newly down.
struct Frame
{
    std::string characters;
    bool backspaceDown = false;
    bool ctrlADown = false;
};

class InputQueue : public ::testing::Test
{
protected:
    InputQueue() : m_context(ImGui::CreateContext()) {}
    ~InputQueue() override { ImGui::DestroyContext(m_context); }

    Frame frame()
    {
        ImGuiIO& io = ImGui::GetIO();
        io.InputQueueCharacters.resize(0);
        m_queue.drain(io);
        Frame f;
        for (const ImWchar c : io.InputQueueCharacters)
            f.characters += static_cast<char>(c);
        f.backspaceDown = io.KeysDown[sf::Keyboard::BackSpace];
        f.ctrlADown = io.KeysDown[sf::Keyboard::A] && io.KeyCtrl;
        return f;
    }

    ImGuiContext* m_context;
    ImGuiInputQueue m_queue;
};

TEST_F(InputQueue, TwentyBackspacesBetweenTwoFramesAreTwentyPresses)
{
    // The designer's finding: 20 Backspaces typed while the editor drew one frame deleted one character.
    for (int i = 0; i < 20; ++i)
    {
        m_queue.push(keyEvent(sf::Keyboard::BackSpace, true));
        m_queue.push(keyEvent(sf::Keyboard::BackSpace, false));
    }
    int presses = 0;
    bool wasDown = false;
    int frames = 0;
    while (!m_queue.empty() && frames < 100)
    {
        const bool down = frame().backspaceDown;
        presses += down && !wasDown ? 1 : 0;
        wasDown = down;
        ++frames;
    }
    EXPECT_EQ(presses, 20);
    EXPECT_EQ(frames, 40) << "one transition per key per frame";
}

TEST_F(InputQueue, CharactersKeepTheirOrderAroundEditingKeys)
{
    // "ab", Backspace, "c": ImGui applies a frame's characters before its keys, so "c" must wait for Backspace's
    // frame to pass; the text ends "ac", not "ab" with the "c" deleted.
    for (const char c : std::string("ab"))
    {
        m_queue.push(keyEvent(static_cast<sf::Keyboard::Key>(sf::Keyboard::A + (c - 'a')), true));
        m_queue.push(textEvent(c));
        m_queue.push(keyEvent(static_cast<sf::Keyboard::Key>(sf::Keyboard::A + (c - 'a')), false));
    }
    m_queue.push(keyEvent(sf::Keyboard::BackSpace, true));
    m_queue.push(keyEvent(sf::Keyboard::BackSpace, false));
    m_queue.push(keyEvent(sf::Keyboard::C, true));
    m_queue.push(textEvent('c'));
    m_queue.push(keyEvent(sf::Keyboard::C, false));
    // Replay what an ImGui text field would do with each frame.
    std::string text;
    for (int i = 0; i < 20 && !m_queue.empty(); ++i)
    {
        const bool wasDown = ImGui::GetIO().KeysDown[sf::Keyboard::BackSpace];
        const Frame f = frame();
        text += f.characters;
        if (f.backspaceDown && !wasDown && !text.empty())
            text.pop_back();
    }
    EXPECT_TRUE(m_queue.empty());
    EXPECT_EQ(text, "ac");
}

TEST_F(InputQueue, CtrlAIsSeenBeforeTheTextThatReplacesTheSelection)
{
    m_queue.push(keyEvent(sf::Keyboard::LControl, true, true));
    m_queue.push(keyEvent(sf::Keyboard::A, true, true));
    m_queue.push(keyEvent(sf::Keyboard::A, false, true));
    m_queue.push(keyEvent(sf::Keyboard::LControl, false));
    m_queue.push(keyEvent(sf::Keyboard::M, true));
    m_queue.push(textEvent('M'));
    const Frame first = frame();
    EXPECT_TRUE(first.ctrlADown);
    EXPECT_EQ(first.characters, "");
    const Frame second = frame();
    EXPECT_EQ(second.characters, "M");
}

} // namespace
} // namespace abalike::app
