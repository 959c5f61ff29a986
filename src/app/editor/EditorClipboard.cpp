#include "editor/EditorClipboard.hpp"

#include "editor/EditorContext.hpp"
#include "editor/EditorSource.hpp"
#include "editor/SceneTools.hpp"

#include "shell/AppContext.hpp"
#include "shell/DataPaths.hpp"
#include "shell/Trace.hpp"

#include <SFML/Window/Clipboard.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/save/AtomicWrite.hpp>
#include <abalike/save/DataDirectory.hpp>
#include <abalike/world/Catalog.hpp>
#include <imgui.h>

namespace abalike::app
{

namespace
{

} // namespace

std::filesystem::path EditorClipboard::userPrefabFolder()
{
    const std::filesystem::path data = defaultDataDirectory();
    return data.empty() ? std::filesystem::path() : data / "prefabs";
}

void EditorClipboard::copySelection(bool cut)
{
    const std::string text = m_ctx.scene().copySelection();
    if (text.empty())
    {
        m_ctx.message = "Nothing to copy: select blocks, pigs or terrain";
        m_ctx.messageIsError = true;
        return;
    }
    sf::Clipboard::setString(sf::String::fromUtf8(text.begin(), text.end()));
    const std::size_t count = m_ctx.scene().selection().size();
    if (cut)
        m_ctx.scene().deleteSelection();
    m_ctx.message = std::string(cut ? "Cut " : "Copied ") + std::to_string(count) +
                    (count == 1 ? " object" : " objects") + " (as level JSON: paste it in any level)";
    m_ctx.messageIsError = false;
    m_ctx.app.trace().write("editor-copy", {{"objects", count}, {"cut", cut}});
}

void EditorClipboard::paste()
{
    const std::basic_string<sf::Uint8> utf8 = sf::Clipboard::getString().toUtf8();
    const std::string text(utf8.begin(), utf8.end());
    const std::string why = m_ctx.scene().paste(text, m_tools.insertionPoint());
    const std::size_t count = m_ctx.scene().selection().size();
    m_ctx.message = why.empty() ? "Pasted " + std::to_string(count) + (count == 1 ? " object" : " objects")
                                : "Cannot paste: " + why;
    m_ctx.messageIsError = !why.empty();
    if (why.empty())
        m_ctx.sayIfNotLanded();
    m_ctx.app.trace().write("editor-paste",
                            {{"objects", why.empty() ? m_ctx.scene().selection().size() : 0}, {"why", why}});
}

void EditorClipboard::insertPrefab(const std::filesystem::path& file)
{
    try
    {
        const EditableLevel prefab = loadLevelForEditing(file.string(), Catalog::builtin());
        if (prefab.level.blocks.empty() && prefab.level.pigs.empty() && prefab.level.terrain.empty())
        {
            m_ctx.message = "Cannot insert " + file.stem().string() + ": it holds no blocks, pigs or terrain";
            m_ctx.messageIsError = true;
        }
        else
        {
            m_tools.hold(prefab.level, "Insert " + file.stem().string());
            m_ctx.message = file.stem().string() + " in hand: click on the scene to drop it (Shift+click: again; Esc: "
                                                   "cancel)";
            m_ctx.messageIsError = false;
        }
    }
    catch (const LevelLoadError& error)
    {
        m_ctx.message = error.issues().empty() ? error.what() : error.issues().front().format();
        m_ctx.messageIsError = true;
    }
    m_ctx.app.trace().write("editor-prefab", {{"file", file.string()}, {"error", m_ctx.messageIsError}});
}

void EditorClipboard::generateHere(GeneratedKind kind, int maxBodies)
{
    const std::string name = generatedKindName(kind);
    try
    {
        if (m_parts.empty())
            m_parts =
                loadGeneratorParts((std::filesystem::path(levelsDirectory()) / "parts").string(), Catalog::builtin());
        const std::optional<LevelDef> structure =
            generateStructure(m_parts, kind, maxBodies, ++m_generated, Catalog::builtin());
        const std::size_t bodies = structure ? structure->blocks.size() + structure->pigs.size() : 0;
        if (structure)
            m_tools.hold(*structure, "Generate " + name);
        m_ctx.message = structure
                            ? "Generated " + name + " " + std::to_string(m_generated) + ": " + std::to_string(bodies) +
                                  " bodies, stands on its own; click on the scene to drop it (Esc: cancel)"
                            : "Cannot generate " + name + ": none of 8 layouts stood on its own";
        m_ctx.messageIsError = !structure;
    }
    catch (const std::exception& error) // a part that does not load, or no part with a pig in the budget
    {
        m_ctx.message = std::string("Cannot generate ") + name + ": " + error.what();
        m_ctx.messageIsError = true;
    }
    m_ctx.app.trace().write(
        "editor-generate",
        {{"kind", name}, {"max_bodies", maxBodies}, {"seed", m_generated}, {"error", m_ctx.messageIsError}});
}

void EditorClipboard::saveSelectionAsPrefab()
{
    const std::string text = m_ctx.scene().copySelection();
    const std::filesystem::path folder = userPrefabFolder();
    if (text.empty() || folder.empty())
    {
        m_ctx.message = text.empty() ? "Nothing to save: select blocks, pigs or terrain"
                                     : "No data folder for prefabs (set HOME or ABALIKE_DATA_DIR)";
        m_ctx.messageIsError = true;
        return;
    }
    // prefabs/LEVEL-N.json with the first free N: saving never overwrites an earlier prefab.
    std::string stem = m_ctx.scene().level().id.empty() ? std::string("prefab") : m_ctx.scene().level().id;
    for (char& c : stem)
        if (c == '/' || c == '\\')
            c = '-';
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    std::filesystem::path path;
    for (int n = 1;; ++n)
    {
        path = folder / (stem + "-" + std::to_string(n) + ".json");
        if (!std::filesystem::exists(path, ec))
            break;
    }
    try
    {
        writeFileAtomically(path, text);
        m_ctx.message = "Saved the selection as the prefab " + path.string();
        m_ctx.messageIsError = false;
    }
    catch (const std::exception& error)
    {
        m_ctx.message = std::string("Cannot save the prefab: ") + error.what();
        m_ctx.messageIsError = true;
    }
}

} // namespace abalike::app
