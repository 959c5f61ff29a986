#pragma once

#include <abalike/design/Generator.hpp>
#include <abalike/design/GeneratorLayouts.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace abalike::app
{

struct EditorContext;
class SceneTools;

/// Copy, cut and paste through the system clipboard (as level JSON, so they work across files and editor windows),
/// and prefabs: any level's bodies inserted as a group (the bundled structure scenes and the designer's own folder).
class EditorClipboard
{
public:
    EditorClipboard(EditorContext& context, SceneTools& tools) : m_ctx(context), m_tools(tools) {}

    void copySelection(bool cut);
    void paste();
    /// Puts the prefab's bodies in hand (SceneTools::hold): the next click on the scene drops them.
    void insertPrefab(const std::filesystem::path& file);
    /// "Generate here": a structure of that kind within maxBodies (abalike generate's layouts), verified to stand on
    /// its own, put in hand: the next click on the scene drops it there onto the surface below as one undo step.
    /// Each call takes the next seed.
    void generateHere(GeneratedKind kind, int maxBodies);
    void saveSelectionAsPrefab();

    /// The designer's own prefabs folder (empty when there is no data folder).
    static std::filesystem::path userPrefabFolder();

private:
    EditorContext& m_ctx;
    SceneTools& m_tools;
    std::vector<GeneratorPart> m_parts; ///< levels/parts/, read on the first "Generate here"
    std::uint64_t m_generated = 0;      ///< structures generated so far: the next one's seed
};

} // namespace abalike::app
