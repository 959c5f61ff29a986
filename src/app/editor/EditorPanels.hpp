#pragma once

namespace abalike::app
{

class EditorClipboard;
struct EditorContext;
class EditorFiles;
class EditorInspector;
class PlayTest;
class SceneTools;

/// The editor's panels around the scene, built every frame with Dear ImGui: the menu bar, the palette of what can
/// be placed, the inspector, the status bar, the findings' tooltip and the files' dialogs. They act through the
/// editor's parts; where each panel went is kept for the mouse (EditorContext::panels).
class EditorPanels
{
public:
    EditorPanels(EditorContext& context, SceneTools& tools, PlayTest& play, EditorFiles& files,
                 EditorClipboard& clipboard, EditorInspector& inspector)
        : m_ctx(context), m_tools(tools), m_play(play), m_files(files), m_clipboard(clipboard), m_inspector(inspector)
    {
    }

    /// This frame's panels (between ImGui's NewFrame and Render).
    void build();

private:
    void menuBar();
    void prefabMenu();
    void palettePanel();
    /// The palette's birds: one button per bird of the catalog, adding it to the end of the launch order.
    void birdButtons(float buttonWidth);
    void statusBar();
    void findingTooltip();

    EditorContext& m_ctx;
    SceneTools& m_tools;
    PlayTest& m_play;
    EditorFiles& m_files;
    EditorClipboard& m_clipboard;
    EditorInspector& m_inspector;
};

} // namespace abalike::app
