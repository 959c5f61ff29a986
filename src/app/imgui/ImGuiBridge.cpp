#include "imgui/ImGuiBridge.hpp"

#include <SFML/Window/Clipboard.hpp>
#include <algorithm>
#include <backends/imgui_impl_opengl2.h>
#include <cmath>
#include <imgui.h>

namespace abalike::app
{

namespace
{

constexpr float kBaseFontPx = 16.0f;

/// Clipboard through SFML (ImGui calls these for Ctrl+C / Ctrl+V in text fields).
const char* clipboardText(void* user)
{
    auto* buffer = static_cast<std::string*>(user);
    *buffer = sf::Clipboard::getString().toAnsiString();
    return buffer->c_str();
}

void setClipboardText(void*, const char* text)
{
    sf::Clipboard::setString(sf::String::fromUtf8(text, text + std::char_traits<char>::length(text)));
}

int mouseIndex(sf::Mouse::Button button)
{
    switch (button)
    {
    case sf::Mouse::Left:
        return 0;
    case sf::Mouse::Right:
        return 1;
    case sf::Mouse::Middle:
        return 2;
    default:
        return -1;
    }
}

std::string& clipboardBuffer()
{
    static std::string buffer;
    return buffer;
}

} // namespace

ImGuiBridge::ImGuiBridge(sf::RenderWindow& window, const std::string& iniPath, const std::string& fontPath)
    : m_window(window), m_iniPath(iniPath), m_fontPath(fontPath)
{
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = m_iniPath.empty() ? nullptr : m_iniPath.c_str();
    io.ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard;
    io.BackendPlatformName = "abalike_sfml";
    io.GetClipboardTextFn = clipboardText;
    io.SetClipboardTextFn = setClipboardText;
    io.ClipboardUserData = &clipboardBuffer();
    // ImGui 1.86 reads keys from io.KeysDown[], indexed by whatever the platform chooses: SFML's key codes.
    io.KeyMap[ImGuiKey_Tab] = sf::Keyboard::Tab;
    io.KeyMap[ImGuiKey_LeftArrow] = sf::Keyboard::Left;
    io.KeyMap[ImGuiKey_RightArrow] = sf::Keyboard::Right;
    io.KeyMap[ImGuiKey_UpArrow] = sf::Keyboard::Up;
    io.KeyMap[ImGuiKey_DownArrow] = sf::Keyboard::Down;
    io.KeyMap[ImGuiKey_PageUp] = sf::Keyboard::PageUp;
    io.KeyMap[ImGuiKey_PageDown] = sf::Keyboard::PageDown;
    io.KeyMap[ImGuiKey_Home] = sf::Keyboard::Home;
    io.KeyMap[ImGuiKey_End] = sf::Keyboard::End;
    io.KeyMap[ImGuiKey_Insert] = sf::Keyboard::Insert;
    io.KeyMap[ImGuiKey_Delete] = sf::Keyboard::Delete;
    io.KeyMap[ImGuiKey_Backspace] = sf::Keyboard::Backspace;
    io.KeyMap[ImGuiKey_Space] = sf::Keyboard::Space;
    io.KeyMap[ImGuiKey_Enter] = sf::Keyboard::Enter;
    io.KeyMap[ImGuiKey_Escape] = sf::Keyboard::Escape;
    io.KeyMap[ImGuiKey_KeyPadEnter] = sf::Keyboard::Enter; // SFML 2.5 has no separate keypad Enter
    io.KeyMap[ImGuiKey_A] = sf::Keyboard::A;
    io.KeyMap[ImGuiKey_C] = sf::Keyboard::C;
    io.KeyMap[ImGuiKey_V] = sf::Keyboard::V;
    io.KeyMap[ImGuiKey_X] = sf::Keyboard::X;
    io.KeyMap[ImGuiKey_Y] = sf::Keyboard::Y;
    io.KeyMap[ImGuiKey_Z] = sf::Keyboard::Z;

    static_cast<void>(m_window.setActive(true)); // the renderer creates its font texture in this GL context
    ImGui_ImplOpenGL2_Init();
    setStyle(1.0f, false);
}

ImGuiBridge::~ImGuiBridge()
{
    static_cast<void>(m_window.setActive(true));
    ImGui_ImplOpenGL2_Shutdown();
    ImGui::DestroyContext();
}

void ImGuiBridge::setStyle(float scale, bool highContrast)
{
    scale = std::clamp(std::round(scale * 8.0f) / 8.0f, 0.5f, 4.0f); // whole steps: no atlas rebuild per pixel
    if (scale != m_scale)
    {
        m_scale = scale;
        buildFonts();
        m_styled = false;
    }
    if (!m_styled || highContrast != m_highContrast)
    {
        m_highContrast = highContrast;
        applyColours();
        m_styled = true;
    }
}

void ImGuiBridge::buildFonts()
{
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    const float px = std::round(kBaseFontPx * m_scale);
    if (!m_fontPath.empty())
    {
        // Latin, Greek (rho, lambda), punctuation, super- and subscripts, arrows and maths: the symbols panels use.
        static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2000, 0x206F, 0x2070,
                                         0x209F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};
        if (io.Fonts->AddFontFromFileTTF(m_fontPath.c_str(), px, nullptr, ranges) == nullptr)
            m_fontPath.clear();
    }
    if (m_fontPath.empty())
    {
        ImFontConfig config;
        config.SizePixels = px;
        io.Fonts->AddFontDefault(&config);
    }
    static_cast<void>(m_window.setActive(true));
    ImGui_ImplOpenGL2_DestroyFontsTexture();
    ImGui_ImplOpenGL2_CreateFontsTexture();
}

void ImGuiBridge::applyColours()
{
    ImGuiStyle& style = ImGui::GetStyle();
    style = ImGuiStyle();
    ImGui::StyleColorsDark(&style);
    style.WindowRounding = 6.0f;
    style.FrameRounding = 4.0f;
    style.GrabRounding = 4.0f;
    style.WindowBorderSize = 1.0f;
    if (m_highContrast)
    {
        // Solid black panels, white text and strong outlines: the settings' high-contrast promise (7:1 or more).
        style.WindowBorderSize = 2.0f;
        style.FrameBorderSize = 1.0f;
        ImVec4* c = style.Colors;
        c[ImGuiCol_Text] = ImVec4(1.0f, 1.0f, 1.0f, 1.0f);
        c[ImGuiCol_TextDisabled] = ImVec4(0.75f, 0.75f, 0.75f, 1.0f);
        c[ImGuiCol_WindowBg] = ImVec4(0.0f, 0.0f, 0.0f, 1.0f);
        c[ImGuiCol_PopupBg] = ImVec4(0.0f, 0.0f, 0.0f, 1.0f);
        c[ImGuiCol_MenuBarBg] = ImVec4(0.0f, 0.0f, 0.0f, 1.0f);
        c[ImGuiCol_Border] = ImVec4(1.0f, 1.0f, 1.0f, 1.0f);
        c[ImGuiCol_FrameBg] = ImVec4(0.12f, 0.12f, 0.12f, 1.0f);
        c[ImGuiCol_FrameBgHovered] = ImVec4(0.25f, 0.25f, 0.1f, 1.0f);
        c[ImGuiCol_Button] = ImVec4(0.1f, 0.1f, 0.35f, 1.0f);
        c[ImGuiCol_ButtonHovered] = ImVec4(0.2f, 0.2f, 0.6f, 1.0f);
        c[ImGuiCol_Header] = ImVec4(0.1f, 0.1f, 0.35f, 1.0f);
        c[ImGuiCol_CheckMark] = ImVec4(1.0f, 1.0f, 0.2f, 1.0f);
        c[ImGuiCol_SliderGrab] = ImVec4(1.0f, 1.0f, 0.2f, 1.0f);
    }
    else
    {
        style.Colors[ImGuiCol_WindowBg].w = 0.92f;
    }
    style.ScaleAllSizes(m_scale);
}

void ImGuiBridge::handleEvent(const sf::Event& event)
{
    ImGuiIO& io = ImGui::GetIO();
    switch (event.type)
    {
    case sf::Event::MouseMoved:
        io.MousePos = ImVec2(static_cast<float>(event.mouseMove.x), static_cast<float>(event.mouseMove.y));
        break;
    case sf::Event::MouseButtonPressed:
    case sf::Event::MouseButtonReleased:
    {
        // Scripted clicks come without a move first: the press says where the pointer is.
        io.MousePos = ImVec2(static_cast<float>(event.mouseButton.x), static_cast<float>(event.mouseButton.y));
        const int index = mouseIndex(event.mouseButton.button);
        if (index < 0)
            break;
        if (event.type == sf::Event::MouseButtonPressed)
        {
            io.MouseDown[index] = true;
            m_pressSeen[index] = false;
            m_releasePending[index] = false;
        }
        else if (m_pressSeen[index])
            io.MouseDown[index] = false;
        else
            m_releasePending[index] = true; // not yet seen down by a frame: released after the next one
        break;
    }
    case sf::Event::MouseWheelScrolled:
        if (event.mouseWheelScroll.wheel == sf::Mouse::VerticalWheel)
            io.MouseWheel += event.mouseWheelScroll.delta;
        else
            io.MouseWheelH += event.mouseWheelScroll.delta;
        break;
    case sf::Event::KeyPressed:
    case sf::Event::KeyReleased:
    case sf::Event::TextEntered:
        m_input.push(event); // each frame takes what it can see apart (ImGuiInputQueue)
        break;
    case sf::Event::LostFocus:
        m_input.clear(io);
        for (bool& button : io.MouseDown)
            button = false;
        break;
    default:
        break;
    }
}

void ImGuiBridge::newFrame(double frameS)
{
    ImGuiIO& io = ImGui::GetIO();
    const sf::Vector2u size = m_window.getSize();
    io.DisplaySize = ImVec2(static_cast<float>(size.x), static_cast<float>(size.y));
    io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
    io.DeltaTime = static_cast<float>(std::max(frameS, 1e-4));
    if (m_frameOpen)
        ImGui::EndFrame(); // a frame built but never drawn
    // A click that came and went between two frames: the last frame saw it down, this one sees it up.
    for (int i = 0; i < 5; ++i)
        if (m_releasePending[i] && m_pressSeen[i])
        {
            io.MouseDown[i] = false;
            m_releasePending[i] = false;
        }
    m_input.drain(io);
    ImGui_ImplOpenGL2_NewFrame();
    ImGui::NewFrame();
    m_frameOpen = true;
    for (int i = 0; i < 5; ++i)
        m_pressSeen[i] = m_pressSeen[i] || io.MouseDown[i];
}

void ImGuiBridge::render()
{
    if (m_frameOpen)
    {
        ImGui::Render();
        m_frameOpen = false;
    }
    // Drawn again as it was when a frame is drawn twice (the app's screenshot redraws the last frame).
    ImDrawData* data = ImGui::GetDrawData();
    if (data == nullptr || !data->Valid)
        return;
    m_window.pushGLStates();
    ImGui_ImplOpenGL2_RenderDrawData(data);
    m_window.popGLStates();
}

bool ImGuiBridge::wantsMouse() const
{
    return ImGui::GetIO().WantCaptureMouse;
}

bool ImGuiBridge::wantsKeyboard() const
{
    return ImGui::GetIO().WantCaptureKeyboard;
}

bool ImGuiBridge::wantsText() const
{
    return ImGui::GetIO().WantTextInput;
}

} // namespace abalike::app
