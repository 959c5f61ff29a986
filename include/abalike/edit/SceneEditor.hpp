#pragma once

#include <abalike/edit/SceneObject.hpp>
#include <abalike/edit/Snapping.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/world/Catalog.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace abalike
{

class History;

/// How a click changes the selection.
enum class SelectMode
{
    Replace, ///< the clicked objects become the selection
    Add,     ///< they are added to it
    Toggle,  ///< each is added, or removed if it was selected
};

/// Which edges or centres alignSelection lines up.
enum class Align
{
    Left,
    CentreX,
    Right,
    Bottom,
    CentreY,
    Top,
};

/// A new sandbox scene: the ground, a slingshot at (0, 1.5), three red birds, Earth's gravity in vacuum, no pigs.
LevelDef emptyScene();

/// The "$schema" a save writes: an existing file's own value as written (none if it has none); for a new file the
/// schema's path relative to it when the schema sits beside it (level.schema.json, schema/level.schema.json, or the
/// same one folder up), else none.
std::string schemaReferenceToWrite(const std::filesystem::path& path, const std::filesystem::path& schemaPath);

/// The level editor's model, headless: a level being edited, the selection, snapping, and the history that makes
/// every edit undoable. The app draws it and turns mouse and keys into these calls; tests drive it directly.
/// Every edit keeps the level loadable: values out of range are refused (the edit returns why), positions and
/// sizes are clamped to what the format accepts.
class SceneEditor
{
public:
    explicit SceneEditor(LevelDef level, const Catalog& catalog = Catalog::builtin());
    ~SceneEditor();
    SceneEditor(const SceneEditor&) = delete;
    SceneEditor& operator=(const SceneEditor&) = delete;

    const LevelDef& level() const { return m_level; }
    /// The base catalog (the scene's own material values and custom bird come on top, see levelCatalog).
    const Catalog& catalog() const { return m_catalog; }

    // ---------------------------------------------------------------- selection
    const std::vector<ObjectRef>& selection() const { return m_selection; }
    bool isSelected(const ObjectRef& ref) const;
    void select(const ObjectRef& ref, SelectMode mode = SelectMode::Replace);
    /// Selects the objects whose bounding boxes lie inside the rectangle (any two corners).
    void selectInRect(double x0, double y0, double x1, double y1, SelectMode mode = SelectMode::Replace);
    void selectAll();
    void clearSelection();
    /// An object's outline for drawing (a convex polygon, counter-clockwise; circles with 64 sides; the slingshot's
    /// frame as a box; a terrain polygon's own corners, in its file's order), in metres.
    std::vector<Vec2> outline(const ObjectRef& ref) const;
    /// The outline an object would have in this scene (the placement ghost).
    std::vector<Vec2> outlineOf(const ObjectDef& def) const;
    /// The object under a point, the one drawn on top first (pigs, then blocks, the slingshot, terrain); none if empty.
    std::optional<ObjectRef> objectAt(double x, double y) const;

    // ---------------------------------------------------------------- edits (each one undo step, unless merged)
    /// Places a block, pig or terrain piece at its snapped position, or moves the slingshot there; selects it.
    ObjectRef place(const ObjectDef& def);
    /// Moves the selection by exactly (dx, dy), no snapping (arrow keys).
    void moveSelection(double dx, double dy);
    /// Starts dragging the selection, grabbed by one of its objects (which snapping aligns; the rest keep formation).
    void beginDrag(const ObjectRef& grabbed);
    /// Moves the dragged selection to (dx, dy) from where the drag began, snapped. All steps of a drag are one edit.
    void dragTo(double dx, double dy);
    void endDrag();
    bool dragging() const { return m_drag.has_value(); }
    /// Turns the selection about its centre (blocks and terrain turn; pigs and the slingshot only move round).
    void rotateSelection(double deltaDeg);
    /// Sets a block's or terrain piece's size keeping its bottom edge and centre line (a circle's w is its diameter).
    /// Returns why not, or an empty string.
    std::string resizeObject(const ObjectRef& ref, double widthM, double heightM, const std::string& mergeKey = {});
    /// Copies the selection one grid step (at least 0.25 m) to the right and selects the copies.
    void duplicateSelection();
    /// Mirrors the selection left to right about the vertical line through its bounding box's centre: positions,
    /// angles (negated), triangles (their right angle moves to the other side) and terrain polygons; one undo step.
    void mirrorSelection();
    /// Removes the selected blocks, pigs and terrain (the slingshot stays).
    void deleteSelection();
    /// Lines the selection's bounding boxes up on the selection's leftmost left edge, lowest bottom, ... (one undo
    /// step; the slingshot stays where it is).
    void alignSelection(Align align);
    /// Spaces the selection evenly between its two outermost objects, left to right or bottom to top: equal gaps
    /// between bounding boxes (at least three objects; one undo step).
    void distributeSelection(bool horizontal);
    /// Replaces several objects' definitions at once (a field edited across a multi-selection): one undo step,
    /// merged with later ones under mergeKey. Returns why not (the first object refused, named), or an empty string.
    std::string changeObjects(const std::vector<ObjectRef>& refs, const std::vector<ObjectDef>& defs,
                              const std::string& label, const std::string& mergeKey = {});

    // ---------------------------------------------------------------- clipboard and prefabs
    /// The selected blocks, pigs and terrain as level JSON (a sandbox scene holding just them): what Copy puts on
    /// the system clipboard, readable by Paste in any file and by any text editor. Empty when nothing is selected.
    std::string copySelection() const;
    /// Adds copies of the blocks, pigs and terrain of `source` as one undo step and selects them. With `at`, the
    /// group moves so its bounding box's bottom centre is there (never below the ground), then settles onto a surface
    /// within snap reach. Returns why not, or an empty string.
    std::string insertBodies(const LevelDef& source, const std::optional<Vec2>& at, const std::string& label);
    /// Where insertBodies would put the blocks, pigs and terrain of `source` (moved to `at`, on the grid, settled),
    /// without adding them: what the editor outlines under the pointer before a drop.
    std::vector<ObjectDef> placedBodies(const LevelDef& source, const std::optional<Vec2>& at) const;
    /// Pastes clipboard text (a copied selection, or any level file's JSON) as insertBodies does. Returns why not:
    /// text that is not a level, or one without bodies.
    std::string paste(std::string_view text, const std::optional<Vec2>& at);

    // ---------------------------------------------------------------- terrain polygon corners
    /// Moves corner `vertex` of terrain polygon `terrain` to (x, y). Returns why not (a polygon that would cross
    /// itself, ...), or an empty string; steps under one mergeKey are one undo step.
    std::string moveVertex(std::size_t terrain, std::size_t vertex, double x, double y,
                           const std::string& mergeKey = {});
    /// Adds a corner in the middle of the edge from `vertex` to the next one. Returns why not, or an empty string.
    std::string insertVertex(std::size_t terrain, std::size_t vertex);
    /// Removes a corner (a polygon keeps at least three). Returns why not, or an empty string.
    std::string removeVertex(std::size_t terrain, std::size_t vertex);
    /// Replaces one object's definition (the property panels). Returns why not, or an empty string.
    std::string changeObject(const ObjectRef& ref, const ObjectDef& def, const std::string& label,
                             const std::string& mergeKey = {});
    /// Sets the level's own properties (id, title, episode, concept, hints, birds, stars, reference shot, time limit,
    /// environment, materials, custom bird, sandbox, ground, slingshot) from `properties`; its object lists are
    /// ignored. Returns why not (the loader's message), or an empty string.
    std::string setProperties(const LevelDef& properties, const std::string& label, const std::string& mergeKey = {});

    // ---------------------------------------------------------------- history
    bool undo();
    bool redo();
    bool canUndo() const;
    bool canRedo() const;
    std::string undoLabel() const;
    std::string redoLabel() const;
    /// Ends a gesture (a slider let go, a key press done): the next edit is a new undo step.
    void endGesture();

    // ---------------------------------------------------------------- snapping
    SnapSettings& snapSettings() { return m_snap; }
    const SnapSettings& snapSettings() const { return m_snap; }
    /// Where def would go if placed or dragged now (objects in `ignore` are not surfaces).
    SnapResult snap(const ObjectDef& def, const std::vector<ObjectRef>& ignore = {}) const;

    // ---------------------------------------------------------------- file
    /// Where Save writes; empty for a scene never saved.
    const std::filesystem::path& path() const { return m_path; }
    void setPath(const std::filesystem::path& path) { m_path = path; }
    /// True when the level differs from what was last saved (or opened).
    bool dirty() const;
    /// Why the scene cannot be saved as a level (a non-sandbox scene without pigs, ...); empty when it can.
    std::vector<LevelIssue> saveProblems() const;
    /// Saves to path (atomically), its "$schema" pointing at schemaPath, and remembers path. The file is read back
    /// before it counts as saved. Returns the geometry problems the saved level has (it opens with them marked;
    /// `abalike check` fails it). Throws LevelLoadError when the scene cannot be saved as a level (see saveProblems),
    /// SaveIoError when the file cannot be written; nothing is written then.
    std::vector<LevelIssue> save(const std::filesystem::path& path, const std::filesystem::path& schemaPath);
    /// Counts the current state as saved (an autosave does not).
    void markSaved();
    /// Counts the current state as not saved (a scene recovered from an autosave).
    void markUnsaved();
    /// Changes since the editor was made: how many edits were pushed, merged or undone (an autosave's trigger).
    std::uint64_t revision() const { return m_revision; }

private:
    struct Drag
    {
        ObjectRef grabbed;
        std::vector<ObjectRef> refs;
        std::vector<ObjectDef> start;
    };

    void push(std::unique_ptr<class EditCommand> command);
    void applySelection(std::vector<ObjectRef> refs);
    std::string validateObject(const ObjectDef& def) const;

    LevelDef m_level;
    const Catalog& m_catalog;
    std::unique_ptr<History> m_history;
    std::vector<ObjectRef> m_selection;
    SnapSettings m_snap;
    std::optional<Drag> m_drag;
    std::filesystem::path m_path;
    std::uint64_t m_savedState = 0;
    std::uint64_t m_revision = 0;
};

} // namespace abalike
