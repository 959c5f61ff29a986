#include "editor/EditorPanels.hpp"

#include "editor/EditorClipboard.hpp"
#include "editor/EditorContext.hpp"
#include "editor/EditorFiles.hpp"
#include "editor/EditorInspector.hpp"
#include "editor/EditorSource.hpp"
#include "editor/PanelStyle.hpp"
#include "editor/PlayTest.hpp"
#include "editor/SceneTools.hpp"
#include "shell/DataPaths.hpp"

#include "shell/AppContext.hpp"
#include "shell/UiMetrics.hpp"

#include <abalike/level/LevelLimits.hpp>
#include <abalike/world/Catalog.hpp>
#include <algorithm>
#include <cstdio>
#include <imgui.h>

namespace abalike::app
{

namespace
{
const char* shapeLabel(BlockShape shape)
{
    switch (shape)
    {
    case BlockShape::Circle:
        return "ball";
    case BlockShape::Triangle:
        return "ramp";
    case BlockShape::HollowBox:
        return "frame";
    case BlockShape::Box:
        break;
    }
    return "box";
}

std::string capitalised(std::string text)
{
    if (!text.empty() && text[0] >= 'a' && text[0] <= 'z')
        text[0] = static_cast<char>(text[0] - 'a' + 'A');
    return text;
}

bool isScienceBirdsPig(const std::string& type)
{
    return type.rfind("sb-", 0) == 0;
}

/// "Small pig"; the Science Birds sizes the importer writes (sb-small) read "SB small", to fit the button.
std::string pigLabel(const std::string& type)
{
    if (isScienceBirdsPig(type))
        return "SB " + type.substr(3);
    return capitalised(type) + " pig";
}
} // namespace

void EditorPanels::build()
{
    m_ctx.panels.clear();
    if (m_ctx.focusScene)
    {
        ImGui::SetWindowFocus(nullptr);
        m_ctx.focusScene = false;
    }
    menuBar();
    if (!m_ctx.playing)
        palettePanel();
    m_inspector.panel();
    if (!m_ctx.playing)
        statusBar(); // in play mode the HUD's own hints have the bottom line
    findingTooltip();
    m_files.dialogs();
}

void EditorPanels::menuBar()
{
    if (!ImGui::BeginMainMenuBar())
        return;
    m_ctx.recordPanel();
    if (ImGui::BeginMenu("File"))
    {
        if (ImGui::MenuItem("New sandbox scene", "Ctrl+N"))
            m_files.request(EditorFiles::Pending::New);
        if (ImGui::MenuItem("Open...", "Ctrl+O"))
            m_files.request(EditorFiles::Pending::Open);
        if (ImGui::MenuItem("Save", "Ctrl+S"))
            m_files.requestSave();
        if (ImGui::MenuItem("Save as...", "Ctrl+Shift+S"))
            m_files.requestSaveAs();
        ImGui::Separator();
        if (ImGui::MenuItem("Close editor", "Esc"))
            m_files.request(EditorFiles::Pending::Leave);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit"))
    {
        const std::string undo = "Undo " + m_ctx.scene().undoLabel();
        const std::string redo = "Redo " + m_ctx.scene().redoLabel();
        if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, m_ctx.scene().canUndo()))
            m_ctx.undo();
        if (ImGui::MenuItem(redo.c_str(), "Ctrl+Y", false, m_ctx.scene().canRedo()))
            m_ctx.redo();
        ImGui::Separator();
        const bool any = !m_ctx.scene().selection().empty();
        if (ImGui::MenuItem("Cut", "Ctrl+X", false, any))
            m_clipboard.copySelection(true);
        if (ImGui::MenuItem("Copy", "Ctrl+C", false, any))
            m_clipboard.copySelection(false);
        if (ImGui::MenuItem("Paste", "Ctrl+V"))
            m_clipboard.paste();
        if (ImGui::MenuItem("Duplicate", "Ctrl+D", false, any))
            m_ctx.scene().duplicateSelection();
        if (ImGui::MenuItem("Mirror left to right", "Ctrl+M", false, any))
            m_ctx.scene().mirrorSelection();
        if (ImGui::MenuItem("Delete", "Del", false, any))
            m_ctx.scene().deleteSelection();
        if (ImGui::MenuItem("Rotate left 15\u00B0", "Q", false, any))
            m_ctx.scene().rotateSelection(15.0);
        if (ImGui::MenuItem("Rotate right 15\u00B0", "E", false, any))
            m_ctx.scene().rotateSelection(-15.0);
        if (ImGui::MenuItem("Select all", "Ctrl+A"))
            m_ctx.scene().selectAll();
        ImGui::Separator();
        const bool several = m_ctx.scene().selection().size() >= 2;
        if (ImGui::BeginMenu("Align", several))
        {
            static constexpr std::pair<const char*, abalike::Align> kAligns[] = {
                {"Left edges", abalike::Align::Left},
                {"Centres (vertical line)", abalike::Align::CentreX},
                {"Right edges", abalike::Align::Right},
                {"Bottoms", abalike::Align::Bottom},
                {"Centres (horizontal line)", abalike::Align::CentreY},
                {"Tops", abalike::Align::Top}};
            for (const auto& [label, align] : kAligns)
                if (ImGui::MenuItem(label))
                    m_ctx.scene().alignSelection(align);
            ImGui::EndMenu();
        }
        const bool three = m_ctx.scene().selection().size() >= 3;
        if (ImGui::MenuItem("Distribute left to right", nullptr, false, three))
            m_ctx.scene().distributeSelection(true);
        if (ImGui::MenuItem("Distribute bottom to top", nullptr, false, three))
            m_ctx.scene().distributeSelection(false);
        m_ctx.scene().endGesture();
        ImGui::EndMenu();
    }
    prefabMenu();
    if (ImGui::BeginMenu("View"))
    {
        SnapSettings& snap = m_ctx.scene().snapSettings();
        ImGui::MenuItem("Snap to grid", "G", &snap.grid);
        ImGui::MenuItem("Snap to surfaces", "M", &snap.surfaces);
        if (ImGui::MenuItem("Fit the scene", "F"))
            m_ctx.fitView();
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Check"))
    {
        if (ImGui::MenuItem("Geometry and reach"))
            m_ctx.checks.runGeometry(m_ctx.scene().level(), m_ctx.scene().revision());
        if (ImGui::MenuItem("Rest test (10 s)"))
            m_ctx.checks.runRest(m_ctx.scene().level(), m_ctx.scene().revision());
        if (ImGui::MenuItem("Solve", nullptr, false, !m_ctx.checks.solving() && !m_ctx.scene().level().pigs.empty()))
            m_ctx.checks.startSolver(m_ctx.scene().level(), m_ctx.scene().revision());
        ImGui::EndMenu();
    }
    if (ImGui::MenuItem(m_ctx.playing ? "Stop (Esc)" : "Play (F5)"))
        m_play.playing() ? m_play.stop() : m_play.start();
    ImGui::EndMainMenuBar();
}

void EditorPanels::prefabMenu()
{
    if (!ImGui::BeginMenu("Insert"))
        return;
    m_ctx.recordPanel();
    const bool any = !m_ctx.scene().selection().empty();
    if (ImGui::MenuItem("Save selection as prefab", nullptr, false, any))
        m_clipboard.saveSelectionAsPrefab();
    ImGui::Separator();
    // Each folder a submenu of its own: together they are longer than a window is tall.
    const auto listFolder = [&](const char* title, const std::filesystem::path& folder)
    {
        if (!ImGui::BeginMenu(title))
            return;
        const std::vector<std::filesystem::path> files =
            folder.empty() ? std::vector<std::filesystem::path>{} : levelFilesForDialogs(folder);
        if (files.empty())
            ImGui::TextDisabled("(none in %s)", folder.string().c_str());
        for (const std::filesystem::path& file : files)
            if (ImGui::MenuItem(file.stem().string().c_str()))
                m_clipboard.insertPrefab(file);
        ImGui::EndMenu();
    };
    // The campaign's castle parts first (tools/levelgen's prefabs as level files), then the stress test scenes.
    listFolder("Castle parts", std::filesystem::path(levelsDirectory()) / "parts");
    listFolder("Structures", std::filesystem::path(levelsDirectory()) / "structures");
    listFolder("My prefabs", EditorClipboard::userPrefabFolder());
    ImGui::Separator();
    // A new structure each time, of the generator's kinds, at the pointer.
    if (ImGui::BeginMenu("Generate here"))
    {
        for (const GeneratedKind kind : generatedKinds())
            if (ImGui::BeginMenu(generatedKindName(kind)))
            {
                for (const auto& [label, bodies] :
                     {std::pair{"small (up to 12 bodies)", 12}, std::pair{"medium (up to 20)", 20},
                      std::pair{"large (up to 30)", 30}})
                    if (ImGui::MenuItem(label))
                        m_clipboard.generateHere(kind, bodies);
                ImGui::EndMenu();
            }
        ImGui::EndMenu();
    }
    ImGui::EndMenu();
}

void EditorPanels::birdButtons(float buttonWidth)
{
    heading("Birds");
    const float swatch = ImGui::GetFrameHeight();
    const float labelWidth = buttonWidth - swatch - ImGui::GetStyle().ItemInnerSpacing.x;
    int column = 0;
    for (const BirdType& bird : Catalog::builtin().birds())
    {
        ImGui::PushID(bird.name.c_str());
        if (column++ % 2 == 1)
            ImGui::SameLine();
        const Rgba& body = bird.look.body;
        ImGui::ColorButton("##look", ImVec4(body[0] / 255.0f, body[1] / 255.0f, body[2] / 255.0f, 1.0f),
                           ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop, ImVec2(swatch, swatch));
        ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
        if (ImGui::Button(capitalised(bird.name).c_str(), ImVec2(labelWidth, 0.0f)))
            m_inspector.addBird(bird.name);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Adds a %s bird (%.3g kg, ability: %s) at the end of the launch order.\nThe Bird tab "
                              "reorders and removes them.",
                              bird.name.c_str(), bird.massKg, std::string(bird.abilityName()).c_str());
        ImGui::PopID();
    }
    const std::vector<std::string>& queue = m_ctx.scene().level().birds;
    std::string order;
    for (const std::string& name : queue)
        order += (order.empty() ? "" : ", ") + name;
    ImGui::TextDisabled("Launch order (%zu of %zu):", queue.size(), limits::kMaxBirds);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", order.c_str());
    ImGui::PopTextWrapPos();
}

void EditorPanels::palettePanel()
{
    const float menu = ImGui::GetFrameHeight();
    const float status = m_ctx.statusBarHeightNow();
    ImGui::SetNextWindowPos(ImVec2(0.0f, menu), ImGuiCond_Always);
    ImGui::SetNextWindowSize(
        ImVec2(m_ctx.sceneArea().left, static_cast<float>(m_ctx.app.ui().windowSize().y) - menu - status),
        ImGuiCond_Always);
    if (!ImGui::Begin("Palette", nullptr, kPanelFlags))
    {
        m_ctx.recordPanel();
        ImGui::End();
        return;
    }
    m_ctx.recordPanel();
    if (ImGui::RadioButton("Select and move (V)", m_tools.tool == SceneTools::Tool::Select))
        m_tools.tool = SceneTools::Tool::Select;

    heading("Blocks (B)");
    const float buttonWidth = 0.5f * (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x);
    for (const Material& material : Catalog::builtin().materials())
    {
        int column = 0;
        for (const BlockShape shape :
             {BlockShape::Box, BlockShape::Circle, BlockShape::Triangle, BlockShape::HollowBox})
        {
            const bool active = m_tools.tool == SceneTools::Tool::Block &&
                                m_tools.blockTemplate.material == material.name && m_tools.blockTemplate.shape == shape;
            const std::string label = material.look.label + " " + shapeLabel(shape);
            if (column++ % 2 == 1)
                ImGui::SameLine();
            if (active)
                ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
            if (ImGui::Button(label.c_str(), ImVec2(buttonWidth, 0.0f)))
            {
                m_tools.tool = SceneTools::Tool::Block;
                m_tools.blockTemplate.material = material.name;
                m_tools.blockTemplate.shape = shape;
                if (shape == BlockShape::Circle)
                    m_tools.blockTemplate.heightM = m_tools.blockTemplate.widthM;
                if (shape == BlockShape::HollowBox)
                {
                    m_tools.blockTemplate.widthM = std::max(m_tools.blockTemplate.widthM, 1.0);
                    m_tools.blockTemplate.heightM = std::max(m_tools.blockTemplate.heightM, 1.0);
                }
            }
            if (active)
                ImGui::PopStyleColor();
        }
    }
    ImGui::PushItemWidth(-FLT_MIN);
    const double minSize = 0.1;
    const double maxSize = 10.0;
    ImGui::TextUnformatted("Width, height (m)");
    double size[2] = {m_tools.blockTemplate.widthM, m_tools.blockTemplate.heightM};
    if (ImGui::InputScalarN("##blocksize", ImGuiDataType_Double, size, 2, nullptr, nullptr, "%.2f"))
    {
        m_tools.blockTemplate.widthM = std::clamp(size[0], minSize, maxSize);
        m_tools.blockTemplate.heightM = m_tools.blockTemplate.shape == BlockShape::Circle
                                            ? m_tools.blockTemplate.widthM
                                            : std::clamp(size[1], minSize, maxSize);
    }
    ImGui::PopItemWidth();

    heading("Pigs (P)");
    // Science Birds' sizes (sb-small, ...) are offered in a level imported from it, where they are already used.
    const std::vector<PigDef>& placed = m_ctx.scene().level().pigs;
    const bool scienceBirds =
        std::any_of(placed.begin(), placed.end(), [](const PigDef& pig) { return isScienceBirdsPig(pig.type); });
    int column = 0;
    for (const PigType& type : Catalog::builtin().pigs())
    {
        if (isScienceBirdsPig(type.name) && !scienceBirds)
            continue;
        if (column++ % 2 == 1)
            ImGui::SameLine();
        const bool active = m_tools.tool == SceneTools::Tool::Pig && m_tools.pigTemplate.type == type.name;
        if (active)
            ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
        const std::string label = pigLabel(type.name);
        if (ImGui::Button(label.c_str(), ImVec2(buttonWidth, 0.0f)))
        {
            m_tools.tool = SceneTools::Tool::Pig;
            m_tools.pigTemplate.type = type.name;
        }
        if (active)
            ImGui::PopStyleColor();
    }

    birdButtons(buttonWidth);

    heading("Scenery");
    if (ImGui::Button("Terrain (T)", ImVec2(buttonWidth, 0.0f)))
        m_tools.chooseTerrainBox();
    ImGui::SameLine();
    if (ImGui::Button("Hill (H)", ImVec2(buttonWidth, 0.0f)))
        m_tools.chooseHill();
    if (ImGui::Button("Slingshot (L)", ImVec2(buttonWidth, 0.0f)))
        m_tools.tool = SceneTools::Tool::Slingshot;

    heading("Snapping");
    SnapSettings& snap = m_ctx.scene().snapSettings();
    ImGui::Checkbox("Grid (G)", &snap.grid);
    ImGui::SameLine();
    ImGui::Checkbox("Surfaces (M)", &snap.surfaces);
    static const double kGrids[] = {0.05, 0.1, 0.25, 0.5, 1.0};
    char current[32];
    std::snprintf(current, sizeof current, "%.2f m", snap.gridM);
    ImGui::PushItemWidth(-FLT_MIN);
    if (ImGui::BeginCombo("##grid", current))
    {
        for (const double g : kGrids)
        {
            char label[32];
            std::snprintf(label, sizeof label, "%.2f m", g);
            if (ImGui::Selectable(label, g == snap.gridM))
                snap.gridM = g;
        }
        ImGui::EndCombo();
    }
    ImGui::PopItemWidth();
    ImGui::Spacing();
    ImGui::TextDisabled("Drag: move  Shift+click: add");
    ImGui::TextDisabled("Q/E: rotate  [ ]: resize");
    ImGui::TextDisabled("Ctrl+C/X/V: copy, cut, paste");
    ImGui::TextDisabled("Ctrl+click a corner: remove");
    ImGui::TextDisabled("Right drag: pan  Wheel: zoom");
    ImGui::End();
}

void EditorPanels::statusBar()
{
    const sf::Vector2f window(m_ctx.app.ui().windowSize());
    const std::string file =
        (m_ctx.scene().path().empty() ? std::string("(not saved yet)") : m_ctx.scene().path().string()) +
        (m_ctx.scene().dirty() ? "  \u2022 modified" : "");
    std::string pointer;
    if (m_tools.pointerOnScene)
    {
        const sf::Vector2f world = m_ctx.view.toWorld(m_tools.pointer);
        char text[64];
        std::snprintf(text, sizeof text, "  x %.2f m, y %.2f m", world.x, world.y);
        pointer = text;
    }
    // The message follows on the same line when it fits; a longer one wraps onto lines of its own below, and the
    // bar grows to hold them (the scene area makes way): never cut at the window's edge.
    const std::string message = m_ctx.message.empty() ? std::string() : "  " + m_ctx.message;
    const float wrapWidth = window.x - 2.0f * ImGui::GetStyle().WindowPadding.x;
    const bool ownLines =
        ImGui::CalcTextSize((file + pointer + message).c_str()).x + 2.0f * ImGui::GetStyle().ItemSpacing.x > wrapWidth;
    const float messageHeight =
        ownLines ? ImGui::CalcTextSize(m_ctx.message.c_str(), nullptr, false, wrapWidth).y : 0.0f;
    const float height = ImGui::GetFrameHeight() + messageHeight + 2.0f * ImGui::GetStyle().WindowPadding.y;
    m_ctx.statusBarHeight = height;
    ImGui::SetNextWindowPos(ImVec2(0.0f, window.y - height), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(window.x, height), ImGuiCond_Always);
    ImGui::Begin("##status", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
    m_ctx.recordPanel();
    ImGui::TextUnformatted((file + pointer).c_str());
    if (!m_ctx.message.empty())
    {
        if (m_ctx.messageIsError)
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.55f, 0.45f, 1.0f));
        if (ownLines)
            ImGui::TextWrapped("%s", m_ctx.message.c_str());
        else
        {
            ImGui::SameLine();
            ImGui::TextUnformatted(message.c_str());
        }
        if (m_ctx.messageIsError)
            ImGui::PopStyleColor();
    }
    ImGui::End();
}

void EditorPanels::findingTooltip()
{
    if (m_ctx.playing || !m_tools.pointerOnScene || ImGui::IsAnyItemHovered())
        return;
    const sf::Vector2f world = m_ctx.view.toWorld(m_tools.pointer);
    const auto hit = m_ctx.scene().objectAt(world.x, world.y);
    if (!hit)
        return;
    const auto findings = m_ctx.checks.findingsOn(*hit);
    if (findings.empty())
        return;
    ImGui::BeginTooltip();
    ImGui::TextUnformatted(describe(m_ctx.scene().level(), *hit).c_str());
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    for (const Finding* finding : findings)
        ImGui::BulletText("%s", finding->message.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

} // namespace abalike::app
