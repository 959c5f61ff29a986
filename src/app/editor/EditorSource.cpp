#include "editor/EditorSource.hpp"

#include <algorithm>

#include "editor/EditorScreen.hpp"
#include "shell/AppContext.hpp"
#include "shell/Navigator.hpp"

#include <abalike/edit/SceneEditor.hpp>
#include <abalike/world/Catalog.hpp>

namespace abalike::app
{

EditorSource sandboxSource()
{
    EditorSource source;
    source.level = emptyScene();
    return source;
}

/// Level files in a folder, sorted, for the open and save dialogs.
std::vector<std::filesystem::path> levelFilesForDialogs(const std::filesystem::path& folder)
{
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec))
        if (entry.path().extension() == ".json" && entry.path().filename() != "campaign.json")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

EditorSource editorSourceFor(const std::filesystem::path& path)
{
    EditorSource source;
    source.path = path;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
    {
        // A new level: an empty scene, named after the file, that the first Save writes there.
        source.level = emptyScene();
        source.level.id = path.stem().string().empty() ? "level" : path.stem().string();
        source.level.title = source.level.id;
        source.level.sandbox = false; // a level to play, unless the designer makes it a sandbox scene
        source.newFile = true;
        return source;
    }
    EditableLevel level = loadLevelForEditing(path.string(), Catalog::builtin());
    source.level = std::move(level.level);
    source.issues = std::move(level.geometryIssues);
    return source;
}

void openEditor(AppContext& app, EditorSource source)
{
    app.navigator().screens().push(std::make_unique<EditorScreen>(app, std::move(source)));
}

} // namespace abalike::app
