#pragma once

#include "editor/EditorClipboard.hpp"
#include "editor/EditorContext.hpp"
#include "editor/EditorFiles.hpp"
#include "editor/EditorInspector.hpp"
#include "editor/EditorPanels.hpp"
#include "editor/EditorSource.hpp"
#include "editor/PlayTest.hpp"
#include "editor/SceneDrawing.hpp"
#include "editor/SceneTools.hpp"
#include "imgui/ImGuiBridge.hpp"
#include "shell/Screen.hpp"

#include <abalike/edit/SceneEditor.hpp>

namespace abalike::app
{

class AppContext;

/// The level editor and sandbox: the scene drawn as the game draws it, Dear ImGui panels around it, mouse and keys
/// to place, select, move, rotate, resize, duplicate and delete with snapping and undo, a play test that fires at
/// the scene and returns to it unchanged, and files. The editing itself is the core's SceneEditor; this screen
/// hands events and frames to its parts: the scene's tools (SceneTools), its drawing (SceneDrawing), the panels
/// (EditorPanels, EditorInspector), the clipboard, the files and the play test, which share an EditorContext.
class EditorScreen : public Screen
{
public:
    static constexpr std::string_view kName = "editor";

    EditorScreen(AppContext& app, EditorSource source);
    ~EditorScreen() override;

    std::string_view name() const override { return kName; }
    bool rightClickIsBack() const override { return false; }
    bool wantsTextInput() const override;
    void handleEvent(const sf::Event& event) override;
    void fixedUpdate(double dtS) override;
    void frameUpdate(double frameS) override;
    void draw(sf::RenderTarget& target) override;
    void onResize(sf::Vector2u size) override;
    bool onCloseRequest() override;

    const SceneEditor& editor() const { return m_ctx.scene(); }

private:
    /// A key the panels left to the scene (EditorKeys.cpp: the editor's shortcuts).
    void handleKey(const sf::Event::KeyEvent& key);
    /// Ctrl with a key: undo, files, clipboard, selection.
    void handleCommandKey(const sf::Event::KeyEvent& key);
    /// [ and ]: the one selected block or terrain piece a grid step wider or narrower (Shift: taller or shorter).
    void resizeByKey(const sf::Event::KeyEvent& key);

    EditorContext m_ctx;
    ImGuiBridge m_imgui;
    SceneTools m_tools;
    SceneDrawing m_drawing;
    PlayTest m_play;
    EditorClipboard m_clipboard;
    EditorFiles m_files;
    EditorInspector m_inspector;
    EditorPanels m_panels;
};

} // namespace abalike::app
