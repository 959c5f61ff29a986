#pragma once

#include "editor/EditorChecks.hpp"
#include "editor/EditorSource.hpp"
#include "editor/EditorView.hpp"
#include "editor/ScenePlay.hpp"
#include "imgui/ImGuiBridge.hpp"
#include "render/Mesh.hpp"
#include "render/WorldRenderer.hpp"
#include "shell/Screen.hpp"

#include <SFML/Graphics/Rect.hpp>
#include <SFML/Graphics/RenderTexture.hpp>
#include <abalike/edit/SceneEditor.hpp>
#include <abalike/game/GameSession.hpp>
#include <array>
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

class App;

/// The level editor and sandbox: the scene drawn as the game draws it, Dear ImGui panels around it (palette,
/// selection, environment, bird, materials, level, checks), mouse and keys to place, select, move, rotate, resize,
/// duplicate and delete with snapping and undo, a play mode that fires at the scene and returns to it unchanged,
/// and files: open, save (atomic, with a $schema path right for where it is saved), autosave to the data
/// directory, and a prompt before unsaved changes are dropped. The editing itself is the core's SceneEditor; this
/// screen draws it and turns input into its calls.
class EditorScreen : public Screen
{
public:
    static constexpr std::string_view kName = "editor";

    EditorScreen(App& app, EditorSource source);
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

    const SceneEditor& editor() const { return *m_editor; }

    /// What a left click on the scene does.
    enum class Tool
    {
        Select,
        Block,
        Pig,
        Terrain,
        Slingshot,
    };

private:
    enum class Pending
    {
        None,
        Leave, ///< leave the editor (Esc, File > Close)
        Quit,  ///< the window is closing
        New,   ///< start a new sandbox scene
        Open,  ///< open another file
    };

    // EditorScreen.cpp: frame, modes, events
    void startPlay();
    /// The play test's camera: the editor's view, over the part of the window the panels leave free (the play is
    /// drawn there, so no panel covers the bird, the HUD or a teaching panel).
    Camera playCamera() const;
    /// Keeps the bird in flight inside the play area by panning the view after it.
    void followBirdInPlay();
    void stopPlay();
    bool playing() const { return m_play != nullptr; }
    void handleKey(const sf::Event::KeyEvent& key);
    void syncPlay();
    void refreshScene();
    void fitView();
    sf::FloatRect sceneArea() const;
    bool pointerOverPanels(sf::Vector2f pixel) const;

    // EditorInput.cpp: the mouse on the scene
    void handleSceneMouse(const sf::Event& event);
    void pressOnScene(sf::Vector2f pixel, bool shift, bool ctrl);
    void moveOnScene(sf::Vector2f pixel);
    void releaseOnScene(sf::Vector2f pixel);
    ObjectDef toolObject(sf::Vector2f world) const;
    std::optional<ObjectRef> resizeHandleAt(sf::Vector2f pixel) const;
    /// A corner of the one selected terrain polygon (or the middle of an edge, which adds a corner) under a pixel.
    struct VertexHandle
    {
        std::size_t terrain = 0;
        std::size_t vertex = 0; ///< the corner, or the edge from this corner to the next
        bool edgeMiddle = false;
    };
    std::optional<VertexHandle> vertexHandleAt(sf::Vector2f pixel) const;
    std::vector<VertexHandle> vertexHandles() const;
    sf::Vector2f vertexHandlePosition(const VertexHandle& handle) const; ///< world
    void pressVertexHandle(const VertexHandle& handle, bool ctrl);

    // EditorGroups.cpp: clipboard, prefabs, the automatic re-check
    void copySelection(bool cut);
    void pasteClipboard();
    /// Where pasted or inserted bodies go: under the pointer when it is on the scene, else the view's centre on the
    /// ground.
    std::array<double, 2> insertionPoint() const;
    void insertPrefab(const std::filesystem::path& file);
    void saveSelectionAsPrefab();
    void prefabMenu();
    void recheckAfterEdits();
    /// The terrain tool with a polygon hill (six corners; its corners then edited on the scene).
    void chooseHillTool();

    // EditorDrawing.cpp: grid, selection, findings, the placement ghost
    void drawOverlay(sf::RenderTarget& target);
    void drawGrid(const Camera& camera, sf::Vector2u size);
    void addOutline(const Camera& camera, const ObjectRef& ref, float widthPx, sf::Color colour);

    // EditorPanels.cpp and the panel files
    void buildUi();
    void menuBar();
    void palettePanel();
    void inspectorPanel();
    void selectionTab();
    /// A multi-selection's common block fields (material, size, angle), edited for all at once.
    void multiSelectionFields(const std::vector<ObjectRef>& selection);
    void environmentTab();
    void birdTab();
    void birdListAndSlingshot(LevelDef& next);
    void materialsTab();
    void levelTab();
    void checksTab();
    void statusBar();
    void findingTooltip();
    /// Applies edited level properties as one undoable edit (merged while a widget is held); says why if refused.
    void setProperties(const LevelDef& properties, const char* label, const char* mergeKey);
    /// Ends the gesture when the last widget was let go.
    void endGestureIfReleased();
    void recordPanel();

    // EditorFiles.cpp: save, open, autosave, prompts
    void requestSave();
    bool saveTo(const std::filesystem::path& path);
    void request(Pending action);
    void carryOut(Pending action);
    void openFile(const std::filesystem::path& path);
    void resetScene(EditorSource source);
    void autosaveIfDue();
    void dialogs();
    void fileDialog();
    void unsavedDialog();
    void recoverDialog();
    std::filesystem::path schemaPath() const;
    std::filesystem::path defaultSavePath() const;

    App& m_app;
    ImGuiBridge m_imgui;
    std::unique_ptr<SceneEditor> m_editor; ///< replaced by New and Open
    EditorView m_view;
    EditorChecks m_checks;
    std::unique_ptr<ScenePlay> m_play;
    sf::RenderTexture m_playTexture; ///< the play test is drawn here, then into the free part of the window

    // The scene as the game would build it, for drawing; rebuilt when the scene changes.
    std::unique_ptr<GameSession> m_scene;
    std::uint64_t m_sceneRevision = ~0ull;
    std::string m_sceneError;
    WorldRenderer m_renderer;
    Mesh m_mesh;

    Tool m_tool = Tool::Select;
    BlockDef m_blockTemplate{BlockShape::Box, "wood", 0.0, 0.0, 1.0, 1.0, 0.0, 0.1};
    PigDef m_pigTemplate{"small", 0.0, 0.0};
    TerrainDef m_terrainTemplate{0.0, 0.0, 4.0, 1.0, 0.0, {}};

    // Pointer state on the scene.
    sf::Vector2f m_pointer;
    bool m_pointerOnScene = false;
    std::optional<sf::Vector2f> m_dragFrom; ///< where a drag of the selection started (world)
    std::optional<sf::Vector2f> m_bandFrom; ///< a selection rectangle's first corner (world)
    bool m_bandAdds = false;
    std::optional<sf::Vector2f> m_panFrom;     ///< panning with the right or middle button (pixels)
    std::optional<ObjectRef> m_resizing;       ///< a block or terrain piece being resized by its handle
    std::optional<VertexHandle> m_vertexDrag;  ///< a terrain polygon's corner being dragged
    std::uint64_t m_recheckedRevision = ~0ull; ///< the revision the automatic re-check last ran on
    bool m_focusScene = false;                 ///< take keyboard focus from the panels at the next frame
    bool m_fieldReleased = false;              ///< an object field was let go this frame: its edit is complete

    std::vector<sf::FloatRect> m_panels; ///< where the panels were drawn in the last frame (window pixels)
    bool m_modalOpen = false;
    bool m_viewFitted = false;
    std::string m_message; ///< the last thing the editor has to say (status bar)
    bool m_messageIsError = false;

    // Files.
    Pending m_pending = Pending::None;
    bool m_showUnsaved = false;
    bool m_showFileDialog = false;
    bool m_fileDialogSaves = false;
    std::string m_fileDialogPath;
    std::optional<EditorSource> m_recovered;
    std::uint64_t m_autosavedRevision = 0;
    bool m_autosaveWritten = false;
    std::chrono::steady_clock::time_point m_lastAutosave = std::chrono::steady_clock::now();
    double m_playAngleDeg = 45.0;
    double m_playSpeedMps = 15.0;
    bool m_aimByPull = false; ///< the launch is set by the band's pull, not the bird's speed
    double m_altitudeM = 0.0;
    std::map<unsigned, std::string> m_textFields; ///< text being typed into the level's fields
};

} // namespace abalike::app
