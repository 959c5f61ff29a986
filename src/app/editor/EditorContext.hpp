#pragma once

#include "editor/EditorChecks.hpp"
#include "editor/EditorSource.hpp"
#include "editor/EditorView.hpp"

#include <SFML/Graphics/Rect.hpp>
#include <abalike/edit/SceneEditor.hpp>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace abalike::app
{

class AppContext;

/// What the editor's parts share: the app, the scene being edited (the core's SceneEditor, which New and Open
/// replace), the view onto it, the checks, the status line and where the panels were drawn in the last frame.
struct EditorContext
{
    EditorContext(AppContext& app, const EditorSource& source);

    SceneEditor& scene() { return *editor; }
    const SceneEditor& scene() const { return *editor; }
    /// Starts editing another scene (New, Open, a recovered autosave): its findings as opened, the view refitted.
    void replaceScene(const EditorSource& source);

    /// The status bar's line: a message, or a problem when error.
    void say(std::string text, bool error = false);
    /// After a place, drop, paste or move: says (as a problem) why a selected block or pig does not land on what is
    /// under it, as `abalike check` would (whyNotLanded); keeps the message otherwise. Returns whether it said so.
    bool sayIfNotLanded();
    /// Undo and redo (keys, menu): a problem the status bar shows belonged to the edit now undone, and goes.
    void undo();
    void redo();

    /// The part of the window the scene is drawn in: between the menu bar and the status bar, right of the palette
    /// and left of the inspector (the palette and the status bar make way while the scene plays).
    sf::FloatRect sceneArea() const;
    /// Notes where the Dear ImGui window being built is, so the mouse over it is the panel's, not the scene's.
    void recordPanel();
    bool pointerOverPanels(sf::Vector2f pixel) const;
    /// Zooms and pans the view onto the whole scene.
    void fitView();
    /// The status bar's height for the panels above it: one line, or as last drawn when it grew.
    float statusBarHeightNow() const;

    AppContext& app;
    std::unique_ptr<SceneEditor> editor;
    std::uint64_t sceneGeneration = 0; ///< counts replaceScene: a new scene's revisions start again
    EditorView view;
    EditorChecks checks;
    std::string message;
    bool messageIsError = false;
    float statusBarHeight = 0.0f;      ///< as the status bar was last drawn (it grows to hold a long message)
    std::vector<sf::FloatRect> panels; ///< where the panels were drawn in the last frame (window pixels)
    bool playing = false;              ///< the scene is being play-tested (PlayTest keeps this)
    bool modalOpen = false;            ///< a dialog is up: it takes every event
    bool viewFitted = false;
    bool focusScene = false;    ///< take keyboard focus from the panels at the next frame
    bool fieldReleased = false; ///< an object field was let go this frame: its edit is complete
};

} // namespace abalike::app
