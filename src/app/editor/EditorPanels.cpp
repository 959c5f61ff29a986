#include "editor/EditorScreen.hpp"

#include "shell/App.hpp"

#include <abalike/world/Catalog.hpp>
#include <cstdio>
#include <imgui.h>

namespace abalike::app
{

namespace
{
/// Panel flags: placed by the editor every frame, never taking focus by appearing (keys stay with the scene).
constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoFocusOnAppearing |
                                         ImGuiWindowFlags_NoSavedSettings;

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

/// A section heading (ImGui 1.86 has no SeparatorText).
void heading(const char* text)
{
    ImGui::Spacing();
    ImGui::TextDisabled("%s", text);
    ImGui::Separator();
}

std::string capitalised(std::string text)
{
    if (!text.empty() && text[0] >= 'a' && text[0] <= 'z')
        text[0] = static_cast<char>(text[0] - 'a' + 'A');
    return text;
}
} // namespace

void EditorScreen::recordPanel()
{
    const ImVec2 pos = ImGui::GetWindowPos();
    const ImVec2 size = ImGui::GetWindowSize();
    m_panels.emplace_back(pos.x, pos.y, size.x, size.y);
}

void EditorScreen::setProperties(const LevelDef& properties, const char* label, const char* mergeKey)
{
    const std::string why = m_editor->setProperties(properties, label, mergeKey);
    if (!why.empty())
    {
        m_message = why;
        m_messageIsError = true;
        return;
    }
    syncPlay();
}

void EditorScreen::endGestureIfReleased()
{
    if (ImGui::IsItemDeactivated())
        m_editor->endGesture();
}

void EditorScreen::buildUi()
{
    m_panels.clear();
    if (m_focusScene)
    {
        ImGui::SetWindowFocus(nullptr);
        m_focusScene = false;
    }
    menuBar();
    if (!playing())
        palettePanel();
    inspectorPanel();
    if (!playing())
        statusBar(); // in play mode the HUD's own hints have the bottom line
    findingTooltip();
    dialogs();
}

void EditorScreen::menuBar()
{
    if (!ImGui::BeginMainMenuBar())
        return;
    recordPanel();
    if (ImGui::BeginMenu("File"))
    {
        if (ImGui::MenuItem("New sandbox scene", "Ctrl+N"))
            request(Pending::New);
        if (ImGui::MenuItem("Open...", "Ctrl+O"))
            request(Pending::Open);
        if (ImGui::MenuItem("Save", "Ctrl+S"))
            requestSave();
        if (ImGui::MenuItem("Save as...", "Ctrl+Shift+S"))
        {
            m_fileDialogSaves = true;
            m_fileDialogPath = defaultSavePath().string();
            m_showFileDialog = true;
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Close editor", "Esc"))
            request(Pending::Leave);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit"))
    {
        const std::string undo = "Undo " + m_editor->undoLabel();
        const std::string redo = "Redo " + m_editor->redoLabel();
        if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, m_editor->canUndo()))
            m_editor->undo();
        if (ImGui::MenuItem(redo.c_str(), "Ctrl+Y", false, m_editor->canRedo()))
            m_editor->redo();
        ImGui::Separator();
        const bool any = !m_editor->selection().empty();
        if (ImGui::MenuItem("Cut", "Ctrl+X", false, any))
            copySelection(true);
        if (ImGui::MenuItem("Copy", "Ctrl+C", false, any))
            copySelection(false);
        if (ImGui::MenuItem("Paste", "Ctrl+V"))
            pasteClipboard();
        if (ImGui::MenuItem("Duplicate", "Ctrl+D", false, any))
            m_editor->duplicateSelection();
        if (ImGui::MenuItem("Mirror left to right", "Ctrl+M", false, any))
            m_editor->mirrorSelection();
        if (ImGui::MenuItem("Delete", "Del", false, any))
            m_editor->deleteSelection();
        if (ImGui::MenuItem("Rotate left 15\u00B0", "Q", false, any))
            m_editor->rotateSelection(15.0);
        if (ImGui::MenuItem("Rotate right 15\u00B0", "E", false, any))
            m_editor->rotateSelection(-15.0);
        if (ImGui::MenuItem("Select all", "Ctrl+A"))
            m_editor->selectAll();
        ImGui::Separator();
        const bool several = m_editor->selection().size() >= 2;
        if (ImGui::BeginMenu("Align", several))
        {
            static constexpr std::pair<const char*, Align> kAligns[] = {{"Left edges", Align::Left},
                                                                        {"Centres (vertical line)", Align::CentreX},
                                                                        {"Right edges", Align::Right},
                                                                        {"Bottoms", Align::Bottom},
                                                                        {"Centres (horizontal line)", Align::CentreY},
                                                                        {"Tops", Align::Top}};
            for (const auto& [label, align] : kAligns)
                if (ImGui::MenuItem(label))
                    m_editor->alignSelection(align);
            ImGui::EndMenu();
        }
        const bool three = m_editor->selection().size() >= 3;
        if (ImGui::MenuItem("Distribute left to right", nullptr, false, three))
            m_editor->distributeSelection(true);
        if (ImGui::MenuItem("Distribute bottom to top", nullptr, false, three))
            m_editor->distributeSelection(false);
        m_editor->endGesture();
        ImGui::EndMenu();
    }
    prefabMenu();
    if (ImGui::BeginMenu("View"))
    {
        SnapSettings& snap = m_editor->snapSettings();
        ImGui::MenuItem("Snap to grid", "G", &snap.grid);
        ImGui::MenuItem("Snap to surfaces", "M", &snap.surfaces);
        if (ImGui::MenuItem("Fit the scene", "F"))
            fitView();
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Check"))
    {
        if (ImGui::MenuItem("Geometry and reach"))
            m_checks.runGeometry(m_editor->level(), m_editor->revision());
        if (ImGui::MenuItem("Rest test (10 s)"))
            m_checks.runRest(m_editor->level(), m_editor->revision());
        if (ImGui::MenuItem("Solve", nullptr, false, !m_checks.solving() && !m_editor->level().pigs.empty()))
            m_checks.startSolver(m_editor->level(), m_editor->revision());
        ImGui::EndMenu();
    }
    if (ImGui::MenuItem(playing() ? "Stop (Esc)" : "Play (F5)"))
        playing() ? stopPlay() : startPlay();
    ImGui::EndMainMenuBar();
}

void EditorScreen::palettePanel()
{
    const float menu = ImGui::GetFrameHeight();
    const float status = ImGui::GetFrameHeight() + 2.0f * ImGui::GetStyle().WindowPadding.y;
    ImGui::SetNextWindowPos(ImVec2(0.0f, menu), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(sceneArea().left, static_cast<float>(m_app.windowSize().y) - menu - status),
                             ImGuiCond_Always);
    if (!ImGui::Begin("Palette", nullptr, kPanelFlags))
    {
        recordPanel();
        ImGui::End();
        return;
    }
    recordPanel();
    if (ImGui::RadioButton("Select and move (V)", m_tool == Tool::Select))
        m_tool = Tool::Select;

    heading("Blocks (B)");
    const float buttonWidth = 0.5f * (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x);
    for (const Material& material : Catalog::builtin().materials())
    {
        int column = 0;
        for (const BlockShape shape :
             {BlockShape::Box, BlockShape::Circle, BlockShape::Triangle, BlockShape::HollowBox})
        {
            const bool active =
                m_tool == Tool::Block && m_blockTemplate.material == material.name && m_blockTemplate.shape == shape;
            const std::string label = material.look.label + " " + shapeLabel(shape);
            if (column++ % 2 == 1)
                ImGui::SameLine();
            if (active)
                ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
            if (ImGui::Button(label.c_str(), ImVec2(buttonWidth, 0.0f)))
            {
                m_tool = Tool::Block;
                m_blockTemplate.material = material.name;
                m_blockTemplate.shape = shape;
                if (shape == BlockShape::Circle)
                    m_blockTemplate.heightM = m_blockTemplate.widthM;
                if (shape == BlockShape::HollowBox)
                {
                    m_blockTemplate.widthM = std::max(m_blockTemplate.widthM, 1.0);
                    m_blockTemplate.heightM = std::max(m_blockTemplate.heightM, 1.0);
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
    double size[2] = {m_blockTemplate.widthM, m_blockTemplate.heightM};
    if (ImGui::InputScalarN("##blocksize", ImGuiDataType_Double, size, 2, nullptr, nullptr, "%.2f"))
    {
        m_blockTemplate.widthM = std::clamp(size[0], minSize, maxSize);
        m_blockTemplate.heightM = m_blockTemplate.shape == BlockShape::Circle ? m_blockTemplate.widthM
                                                                              : std::clamp(size[1], minSize, maxSize);
    }
    ImGui::PopItemWidth();

    heading("Pigs (P)");
    int column = 0;
    for (const PigType& type : Catalog::builtin().pigs())
    {
        if (column++ % 2 == 1)
            ImGui::SameLine();
        const bool active = m_tool == Tool::Pig && m_pigTemplate.type == type.name;
        if (active)
            ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
        const std::string label = capitalised(type.name) + " pig";
        if (ImGui::Button(label.c_str(), ImVec2(buttonWidth, 0.0f)))
        {
            m_tool = Tool::Pig;
            m_pigTemplate.type = type.name;
        }
        if (active)
            ImGui::PopStyleColor();
    }

    heading("Scenery");
    if (ImGui::Button("Terrain (T)", ImVec2(buttonWidth, 0.0f)))
    {
        m_tool = Tool::Terrain;
        m_terrainTemplate = TerrainDef{0.0, 0.0, 4.0, 1.0, 0.0, {}};
    }
    ImGui::SameLine();
    if (ImGui::Button("Hill (H)", ImVec2(buttonWidth, 0.0f)))
        chooseHillTool();
    if (ImGui::Button("Slingshot (L)", ImVec2(buttonWidth, 0.0f)))
        m_tool = Tool::Slingshot;

    heading("Snapping");
    SnapSettings& snap = m_editor->snapSettings();
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

void EditorScreen::statusBar()
{
    const float height = ImGui::GetFrameHeight() + 2.0f * ImGui::GetStyle().WindowPadding.y;
    const sf::Vector2f window(m_app.windowSize());
    ImGui::SetNextWindowPos(ImVec2(0.0f, window.y - height), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(window.x, height), ImGuiCond_Always);
    ImGui::Begin("##status", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
    recordPanel();
    const std::string file = m_editor->path().empty() ? std::string("(not saved yet)") : m_editor->path().string();
    ImGui::Text("%s%s", file.c_str(), m_editor->dirty() ? "  \u2022 modified" : "");
    ImGui::SameLine();
    if (m_pointerOnScene)
    {
        const sf::Vector2f world = m_view.toWorld(m_pointer);
        ImGui::Text("  x %.2f m, y %.2f m", world.x, world.y);
        ImGui::SameLine();
    }
    if (!m_message.empty())
    {
        if (m_messageIsError)
            ImGui::TextColored(ImVec4(1.0f, 0.55f, 0.45f, 1.0f), "  %s", m_message.c_str());
        else
            ImGui::Text("  %s", m_message.c_str());
    }
    ImGui::End();
}

void EditorScreen::findingTooltip()
{
    if (playing() || !m_pointerOnScene || ImGui::IsAnyItemHovered())
        return;
    const sf::Vector2f world = m_view.toWorld(m_pointer);
    const auto hit = m_editor->objectAt(world.x, world.y);
    if (!hit)
        return;
    const auto findings = m_checks.findingsOn(*hit);
    if (findings.empty())
        return;
    ImGui::BeginTooltip();
    ImGui::TextUnformatted(describe(m_editor->level(), *hit).c_str());
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    for (const Finding* finding : findings)
        ImGui::BulletText("%s", finding->message.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

} // namespace abalike::app
