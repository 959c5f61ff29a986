// The editor's group tools: copy, cut and paste through the system clipboard (as level JSON, so they work across
// files and editor windows), prefabs (any level's bodies inserted as a group: the bundled structure scenes and the
// designer's own folder), and the findings kept fresh after every edit.
#include "editor/EditorScreen.hpp"

#include "shell/App.hpp"
#include "shell/DataPaths.hpp"

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

/// Above this many bodies the rest test takes long enough to stall the editor; it is then re-run by hand.
constexpr std::size_t kAutoRestBodies = 200;

std::filesystem::path userPrefabFolder()
{
    const std::filesystem::path data = defaultDataDirectory();
    return data.empty() ? std::filesystem::path() : data / "prefabs";
}

} // namespace

void EditorScreen::copySelection(bool cut)
{
    const std::string text = m_editor->copySelection();
    if (text.empty())
    {
        m_message = "Nothing to copy: select blocks, pigs or terrain";
        m_messageIsError = true;
        return;
    }
    sf::Clipboard::setString(sf::String::fromUtf8(text.begin(), text.end()));
    const std::size_t count = m_editor->selection().size();
    if (cut)
        m_editor->deleteSelection();
    m_message = std::string(cut ? "Cut " : "Copied ") + std::to_string(count) + (count == 1 ? " object" : " objects") +
                " (as level JSON: paste it in any level)";
    m_messageIsError = false;
    m_app.trace().write("editor-copy", {{"objects", count}, {"cut", cut}});
}

std::array<double, 2> EditorScreen::insertionPoint() const
{
    if (m_pointerOnScene)
    {
        const sf::Vector2f world = m_view.toWorld(m_pointer);
        return {world.x, world.y};
    }
    const sf::FloatRect area = sceneArea();
    const sf::Vector2f centre = m_view.toWorld({area.left + 0.5f * area.width, area.top + 0.5f * area.height});
    return {centre.x, m_editor->level().groundY};
}

void EditorScreen::pasteClipboard()
{
    const std::basic_string<sf::Uint8> utf8 = sf::Clipboard::getString().toUtf8();
    const std::string text(utf8.begin(), utf8.end());
    const std::string why = m_editor->paste(text, insertionPoint());
    m_message =
        why.empty() ? "Pasted " + std::to_string(m_editor->selection().size()) + " objects" : "Cannot paste: " + why;
    m_messageIsError = !why.empty();
    m_app.trace().write("editor-paste", {{"objects", why.empty() ? m_editor->selection().size() : 0}, {"why", why}});
}

void EditorScreen::insertPrefab(const std::filesystem::path& file)
{
    try
    {
        const EditableLevel prefab = loadLevelForEditing(file.string(), Catalog::builtin());
        const std::string why =
            m_editor->insertBodies(prefab.level, insertionPoint(), "Insert " + file.stem().string());
        m_message =
            why.empty() ? "Inserted " + file.stem().string() : "Cannot insert " + file.stem().string() + ": " + why;
        m_messageIsError = !why.empty();
    }
    catch (const LevelLoadError& error)
    {
        m_message = error.issues().empty() ? error.what() : error.issues().front().format();
        m_messageIsError = true;
    }
    m_app.trace().write("editor-prefab", {{"file", file.string()}, {"error", m_messageIsError}});
}

void EditorScreen::saveSelectionAsPrefab()
{
    const std::string text = m_editor->copySelection();
    const std::filesystem::path folder = userPrefabFolder();
    if (text.empty() || folder.empty())
    {
        m_message = text.empty() ? "Nothing to save: select blocks, pigs or terrain"
                                 : "No data folder for prefabs (set HOME or ABALIKE_DATA_DIR)";
        m_messageIsError = true;
        return;
    }
    // prefabs/LEVEL-N.json with the first free N: saving never overwrites an earlier prefab.
    std::string stem = m_editor->level().id.empty() ? std::string("prefab") : m_editor->level().id;
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
        m_message = "Saved the selection as the prefab " + path.string();
        m_messageIsError = false;
    }
    catch (const std::exception& error)
    {
        m_message = std::string("Cannot save the prefab: ") + error.what();
        m_messageIsError = true;
    }
}

void EditorScreen::prefabMenu()
{
    if (!ImGui::BeginMenu("Insert"))
        return;
    recordPanel();
    const bool any = !m_editor->selection().empty();
    if (ImGui::MenuItem("Save selection as prefab", nullptr, false, any))
        saveSelectionAsPrefab();
    ImGui::Separator();
    const auto listFolder = [&](const char* title, const std::filesystem::path& folder)
    {
        ImGui::TextDisabled("%s", title);
        const std::vector<std::filesystem::path> files =
            folder.empty() ? std::vector<std::filesystem::path>{} : levelFilesIn(folder);
        if (files.empty())
            ImGui::TextDisabled("  (none in %s)", folder.string().c_str());
        for (const std::filesystem::path& file : files)
            if (ImGui::MenuItem(("  " + file.stem().string()).c_str()))
                insertPrefab(file);
    };
    listFolder("Structures", std::filesystem::path(levelsDirectory()) / "structures");
    listFolder("My prefabs", userPrefabFolder());
    ImGui::EndMenu();
}

void EditorScreen::chooseHillTool()
{
    m_tool = Tool::Terrain;
    m_terrainTemplate = TerrainDef{};
    m_terrainTemplate.points = {{-3.0, -0.75}, {3.0, -0.75}, {2.0, 0.25}, {0.5, 0.75}, {-0.5, 0.75}, {-2.0, 0.25}};
    m_terrainTemplate.widthM = 6.0;
    m_terrainTemplate.heightM = 1.5;
}

void EditorScreen::recheckAfterEdits()
{
    // After every edit (once a drag or slider is let go): the geometry check always, the rest test when it has
    // run on this scene and the scene is small enough to test without a stall. Findings never go stale unseen.
    const bool gesture = m_editor->dragging() || m_vertexDrag || m_resizing || ImGui::IsAnyItemActive();
    if (playing() || gesture || m_editor->revision() == m_recheckedRevision)
        return;
    const bool firstLook = m_recheckedRevision == ~0ull;
    m_recheckedRevision = m_editor->revision();
    if (firstLook)
        return; // the scene as opened keeps its opening findings
    const LevelDef& level = m_editor->level();
    m_checks.runGeometry(level, m_editor->revision());
    const bool rest = m_checks.ranOn(FindingSource::Rest) && level.blocks.size() + level.pigs.size() <= kAutoRestBodies;
    if (rest)
        m_checks.runRest(level, m_editor->revision());
    std::size_t geometry = 0;
    for (const Finding& finding : m_checks.findings())
        geometry += finding.source == FindingSource::Geometry ? 1 : 0;
    m_app.trace().write("editor-recheck",
                        {{"revision", m_editor->revision()}, {"geometry_findings", geometry}, {"rest", rest}});
}

} // namespace abalike::app
