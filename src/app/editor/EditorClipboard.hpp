#pragma once

#include <filesystem>

namespace abalike::app
{

struct EditorContext;
class SceneTools;

/// Copy, cut and paste through the system clipboard (as level JSON, so they work across files and editor windows),
/// and prefabs: any level's bodies inserted as a group (the bundled structure scenes and the designer's own folder).
class EditorClipboard
{
public:
    EditorClipboard(EditorContext& context, const SceneTools& tools) : m_ctx(context), m_tools(tools) {}

    void copySelection(bool cut);
    void paste();
    void insertPrefab(const std::filesystem::path& file);
    void saveSelectionAsPrefab();

    /// The designer's own prefabs folder (empty when there is no data folder).
    static std::filesystem::path userPrefabFolder();

private:
    EditorContext& m_ctx;
    const SceneTools& m_tools;
};

} // namespace abalike::app
