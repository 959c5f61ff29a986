#pragma once

#include <abalike/level/LevelIO.hpp>

#include <filesystem>
#include <vector>

namespace abalike::app
{

class AppContext;

/// What the editor opens: a scene, the file it saves to, and the geometry problems it was opened with.
struct EditorSource
{
    LevelDef level;
    std::filesystem::path path;     ///< empty: a scene never saved (Save asks where)
    std::vector<LevelIssue> issues; ///< geometry problems found when it was read, marked on the objects
    bool newFile = false;           ///< the path does not exist yet; the first Save creates it
};

/// An empty sandbox scene (ground, slingshot, three red birds), not yet saved anywhere.
EditorSource sandboxSource();

/// A level file to edit. A path that does not exist yet gives an empty scene that saves there; a file that cannot
/// be read or whose JSON or format is invalid throws LevelLoadError (every problem, as `check` prints them); a
/// level with geometry problems opens with them listed.
/// Level files in a folder (campaign manifests left out), sorted: the open and save dialogs' lists, the prefabs.
std::vector<std::filesystem::path> levelFilesForDialogs(const std::filesystem::path& folder);

EditorSource editorSourceFor(const std::filesystem::path& path);

/// Opens the editor over the screens already there (title menu's Sandbox, level select's Edit).
void openEditor(AppContext& app, EditorSource source);

} // namespace abalike::app
