#pragma once

#include "imgui/ImGuiInputQueue.hpp"

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Window/Event.hpp>
#include <string>

namespace abalike::app
{

/// Dear ImGui 1.86 in an SFML window. No SFML binding is packaged for Debian, so this is the small bridge: SFML
/// events become ImGui's input (io.KeysDown through io.KeyMap, since 1.86 predates the 1.87 event API; the mouse
/// position, buttons and wheel; typed text), and ImGui's draw lists are rendered by its own OpenGL2 backend inside
/// SFML's pushGLStates/popGLStates, so SFML's drawing before and after is undisturbed.
///
/// One ImGui context exists while a bridge does (the editor screen owns one). Fonts come from the game's TTF, sized
/// by the UI scale; the style follows the high-contrast setting.
class ImGuiBridge
{
public:
    /// iniPath: where ImGui keeps its window layout (imgui.ini in the data directory); empty keeps none (scripted
    /// runs never write the player's files). fontPath: a TTF file; empty uses ImGui's built-in font.
    ImGuiBridge(sf::RenderWindow& window, const std::string& iniPath, const std::string& fontPath);
    ~ImGuiBridge();
    ImGuiBridge(const ImGuiBridge&) = delete;
    ImGuiBridge& operator=(const ImGuiBridge&) = delete;

    /// Text size (1 = 16 px at 1280x720 and 100 % text scale) and contrast; rebuilds the font atlas only when the
    /// size changed.
    void setStyle(float scale, bool highContrast);

    /// Feeds one event to ImGui.
    void handleEvent(const sf::Event& event);
    /// Starts a frame: window size, time step, mouse and keys as the events left them.
    void newFrame(double frameS);
    /// Ends the frame and draws what it built, over whatever SFML drew before; drawing again without a new frame
    /// draws the same again.
    void render();

    /// ImGui has the pointer (it is over a panel, or dragging a widget): the scene must not act on mouse events.
    bool wantsMouse() const;
    /// A widget has keyboard focus (a text field, a slider being typed into): the scene must not act on keys.
    bool wantsKeyboard() const;
    /// A text field is being edited.
    bool wantsText() const;

    /// The size the fonts were built for.
    float scale() const { return m_scale; }

private:
    void buildFonts();
    void applyColours();

    sf::RenderWindow& m_window;
    std::string m_iniPath;
    std::string m_fontPath;
    float m_scale = 0.0f;
    bool m_highContrast = false;
    bool m_styled = false;
    bool m_frameOpen = false;
    /// ImGui 1.86 samples the buttons once per frame, so a press and its release between two frames would be lost:
    /// such a release waits until a frame has seen the button down.
    bool m_releasePending[5] = {};
    bool m_pressSeen[5] = {}; ///< a frame has seen the button down since it was pressed
    ImGuiInputQueue m_input;
};

} // namespace abalike::app
