#include "editor/EditorInspector.hpp"

#include "editor/EditorContext.hpp"
#include "editor/MixedFields.hpp"
#include "editor/PanelStyle.hpp"
#include "editor/PlayTest.hpp"
#include "editor/SceneDrawing.hpp"

#include "shell/AppContext.hpp"
#include "shell/PlayerSettings.hpp"
#include "shell/UiMetrics.hpp"

#include <abalike/edit/Snapping.hpp>
#include <abalike/flight/GravityPresets.hpp>
#include <abalike/flight/StandardAtmosphere.hpp>
#include <abalike/level/LevelCatalog.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <abalike/level/LevelLimits.hpp>
#include <abalike/level/WorldTheme.hpp>
#include <abalike/world/BirdBody.hpp>
#include <box2d/b2_body.h>
#include <cstdio>
#include <imgui.h>
#include <imgui_internal.h>
#include <imgui_stdlib.h>
#include <regex>

namespace abalike::app
{

namespace
{

/// A hill's (a polygon's) x, y, width and height are its bounding box: moving or resizing the box moves and scales
/// its corners with it (the file keeps only the corners, so a box edit that left them would change nothing).
void fitPolygonToBox(TerrainDef& terrain, const TerrainDef& before)
{
    const double sx = before.widthM > 0.0 ? std::max(terrain.widthM, 0.01) / before.widthM : 1.0;
    const double sy = before.heightM > 0.0 ? std::max(terrain.heightM, 0.01) / before.heightM : 1.0;
    for (auto& point : terrain.points)
        point = {terrain.x + (point.x - before.x) * sx, terrain.y + (point.y - before.y) * sy};
}
bool sliderDouble(const char* label, double& value, double min, double max, const char* format,
                  ImGuiSliderFlags flags = 0)
{
    return ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &min, &max, format, flags);
}

/// A number typed in: true on every edit, so the scene follows as it is typed (one undo step per field); `released`
/// is set when the field is let go.
bool inputDouble(const char* label, double& value, bool& released, const char* format = "%.3f")
{
    const bool changed = ImGui::InputDouble(label, &value, 0.0, 0.0, format);
    released |= ImGui::IsItemDeactivated();
    return changed;
}

const char* shapeNames[] = {"box", "circle", "triangle", "hollow_box"};

/// A drop-down of the catalog's names (materials, pig types): true when another one is picked into name.
template <class Item>
bool catalogCombo(const char* label, const std::vector<Item>& items, std::string& name)
{
    std::vector<const char*> names;
    int chosen = 0;
    for (std::size_t i = 0; i < items.size(); ++i)
    {
        names.push_back(items[i].name.c_str());
        if (items[i].name == name)
            chosen = static_cast<int>(i);
    }
    const int before = chosen;
    if (!ImGui::Combo(label, &chosen, names.data(), static_cast<int>(names.size())) || chosen == before)
        return false;
    name = items[static_cast<std::size_t>(chosen)].name;
    return true;
}

/// The loader's messages name objects by JSON pointer ("overlaps /blocks/0"); the editor names them as it lists them.
std::string readablePointers(const LevelDef& level, std::string text)
{
    static const std::regex pointer(R"(/(blocks|pigs|terrain)/\d+)");
    std::string out;
    std::sregex_iterator it(text.begin(), text.end(), pointer);
    std::size_t last = 0;
    for (; it != std::sregex_iterator(); ++it)
    {
        out += text.substr(last, static_cast<std::size_t>(it->position()) - last);
        const auto ref = objectOfPointer(it->str());
        out += ref ? describe(level, *ref) : it->str();
        last = static_cast<std::size_t>(it->position() + it->length());
    }
    return out + text.substr(last);
}
} // namespace

void EditorInspector::setProperties(const LevelDef& properties, const char* label, const char* mergeKey)
{
    const std::string why = m_ctx.scene().setProperties(properties, label, mergeKey);
    if (!why.empty())
    {
        m_ctx.message = why;
        m_ctx.messageIsError = true;
        return;
    }
    m_play.sync();
}

void EditorInspector::addBird(const std::string& name)
{
    LevelDef next = m_ctx.scene().level();
    if (next.birds.size() >= limits::kMaxBirds)
    {
        m_ctx.message = "The level already has " + std::to_string(limits::kMaxBirds) +
                        " birds, as many as a level may; remove one in the Bird tab first.";
        m_ctx.messageIsError = true;
        return;
    }
    next.birds.push_back(name);
    const std::string label = "Add a " + name + " bird";
    setProperties(next, label.c_str(), "");
}

void EditorInspector::endGestureIfReleased()
{
    if (ImGui::IsItemDeactivated())
        m_ctx.scene().endGesture();
}

void EditorInspector::panel()
{
    const float menu = ImGui::GetFrameHeight();
    const float status = m_ctx.statusBarHeightNow();
    const sf::Vector2f window(m_ctx.app.ui().windowSize());
    const float width = window.x - m_ctx.sceneArea().left - m_ctx.sceneArea().width;
    ImGui::SetNextWindowPos(ImVec2(window.x - width, menu), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, window.y - menu - status), ImGuiCond_Always);
    ImGui::Begin(m_ctx.playing ? "Sandbox (playing)" : "Inspector", nullptr, kPanelFlags);
    m_ctx.recordPanel();
    if (ImGui::BeginTabBar("tabs"))
    {
        if (!m_ctx.playing && ImGui::BeginTabItem("Object"))
        {
            selectionTab();
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Bird"))
        {
            birdTab();
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Air"))
        {
            environmentTab();
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Materials"))
        {
            materialsTab();
            ImGui::EndTabItem();
        }
        if (!m_ctx.playing && ImGui::BeginTabItem("Level"))
        {
            levelTab();
            ImGui::EndTabItem();
        }
        if (!m_ctx.playing && ImGui::BeginTabItem("Checks"))
        {
            checksTab();
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    ImGui::End();
}

void EditorInspector::selectionTab()
{
    const auto& selection = m_ctx.scene().selection();
    if (selection.empty())
    {
        ImGui::TextWrapped("Nothing selected. Click an object, drag a rectangle around several, or pick something "
                           "from the palette and click the scene to place it.");
        return;
    }
    if (selection.size() > 1)
    {
        ImGui::Text("%zu objects selected", selection.size());
        multiSelectionFields(selection);
    }
    else
    {
        const ObjectRef ref = selection[0];
        ImGui::TextUnformatted(describe(m_ctx.scene().level(), ref).c_str());
        // Its mass as the world builds it (the scene's own material values included).
        if (m_drawing.session() && (ref.kind == ObjectKind::Block || ref.kind == ObjectKind::Pig))
            for (const Entity& entity : m_drawing.session()->world().entities())
                if (entity.body != nullptr && entity.defIndex == static_cast<int>(ref.index) &&
                    entity.kind == (ref.kind == ObjectKind::Block ? EntityKind::Block : EntityKind::Pig))
                {
                    ImGui::SameLine();
                    ImGui::TextDisabled("  %.3g kg, breaks at %.3g N s", static_cast<double>(entity.body->GetMass()),
                                        entity.maxHealth);
                }
        ObjectDef def = objectDef(m_ctx.scene().level(), ref);
        bool changed = false;
        const char* key = "";
        ImGui::PushItemWidth(-110.0f * m_ctx.app.ui().scale());
        if (auto* block = std::get_if<BlockDef>(&def))
        {
            int shape = static_cast<int>(block->shape);
            if (ImGui::Combo("Shape", &shape, shapeNames, 4))
            {
                block->shape = static_cast<BlockShape>(shape);
                if (block->shape == BlockShape::Circle)
                    block->heightM = block->widthM;
                changed = true;
            }
            changed |= catalogCombo("Material", Catalog::builtin().materials(), block->material);
            changed |= inputDouble("x (m)", block->x, m_ctx.fieldReleased);
            changed |= inputDouble("y (m)", block->y, m_ctx.fieldReleased);
            changed |= inputDouble(block->shape == BlockShape::Circle ? "Diameter (m)" : "Width (m)", block->widthM,
                                   m_ctx.fieldReleased);
            if (block->shape != BlockShape::Circle)
                changed |= inputDouble("Height (m)", block->heightM, m_ctx.fieldReleased);
            else
                block->heightM = block->widthM;
            if (block->shape != BlockShape::Circle)
                changed |= inputDouble("Angle (\u00B0)", block->angleDeg, m_ctx.fieldReleased, "%.1f");
            if (block->shape == BlockShape::HollowBox)
                changed |= inputDouble("Wall (m)", block->wallM, m_ctx.fieldReleased);
            key = "object";
        }
        else if (auto* pig = std::get_if<PigDef>(&def))
        {
            changed |= catalogCombo("Type", Catalog::builtin().pigs(), pig->type);
            changed |= inputDouble("x (m)", pig->x, m_ctx.fieldReleased);
            changed |= inputDouble("y (m)", pig->y, m_ctx.fieldReleased);
        }
        else if (auto* terrain = std::get_if<TerrainDef>(&def))
        {
            const TerrainDef before = *terrain;
            changed |= inputDouble("x (m)", terrain->x, m_ctx.fieldReleased);
            changed |= inputDouble("y (m)", terrain->y, m_ctx.fieldReleased);
            changed |= inputDouble("Width (m)", terrain->widthM, m_ctx.fieldReleased);
            changed |= inputDouble("Height (m)", terrain->heightM, m_ctx.fieldReleased);
            if (!terrain->isPolygon())
                changed |= inputDouble("Angle (\u00B0)", terrain->angleDeg, m_ctx.fieldReleased, "%.1f");
            else if (changed)
                fitPolygonToBox(*terrain, before);
        }
        else if (auto* sling = std::get_if<SlingshotDef>(&def))
        {
            changed |= inputDouble("x (m)", sling->x, m_ctx.fieldReleased);
            changed |= inputDouble("Pouch y (m)", sling->y, m_ctx.fieldReleased);
        }
        ImGui::PopItemWidth();
        (void)key;
        if (changed)
        {
            // Typed values are checked as the loader would; a value it refuses waits in the field until it is fixed.
            const std::string why =
                m_ctx.scene().changeObject(ref, def, "Edit " + describe(m_ctx.scene().level(), ref), "object-fields");
            m_ctx.message = why;
            m_ctx.messageIsError = !why.empty();
        }
        // Typing into one field is one undo step; the next field, or the same one later, is another.
        if (m_ctx.fieldReleased)
            m_ctx.scene().endGesture();
        m_ctx.fieldReleased = false;
        for (const Finding* finding : m_ctx.checks.findingsOn(ref))
        {
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.5f, 0.45f, 1.0f));
            ImGui::TextWrapped("! %s", readablePointers(m_ctx.scene().level(), finding->message).c_str());
            ImGui::PopStyleColor();
        }
    }
    ImGui::Spacing();
    if (ImGui::Button("Duplicate"))
        m_ctx.scene().duplicateSelection();
    ImGui::SameLine();
    if (ImGui::Button("Delete"))
        m_ctx.scene().deleteSelection();
    ImGui::SameLine();
    if (ImGui::Button("\u21BA 15\u00B0"))
    {
        m_ctx.scene().rotateSelection(15.0);
        m_ctx.scene().endGesture();
    }
    ImGui::SameLine();
    if (ImGui::Button("\u21BB 15\u00B0"))
    {
        m_ctx.scene().rotateSelection(-15.0);
        m_ctx.scene().endGesture();
    }
}

void EditorInspector::environmentTab()
{
    LevelDef next = m_ctx.scene().level();
    EnvironmentDef& env = next.environment;
    ImGui::PushItemWidth(-120.0f * m_ctx.app.ui().scale());
    heading("Gravity");
    if (sliderDouble("g (m/s\u00B2)", env.gravity, 0.0, limits::kMaxGravity, "%.2f", ImGuiSliderFlags_Logarithmic))
        setProperties(next, "Gravity", "gravity");
    endGestureIfReleased();
    for (const GravityPreset& preset : gravityPresets())
    {
        const std::string label(preset.name);
        if (ImGui::Button(label.c_str()))
        {
            // A world brings its air: Mars with Earth's air would teach the wrong drag.
            env.gravity = preset.gravity;
            env.airDensity = preset.airDensity;
            if (preset.airDensity <= 0.0)
            {
                env.windX = env.windY = 0.0; // wind acts only through drag
                env.gusts.reset();
            }
            setProperties(next, "World preset", "");
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("g %.2f m/s\u00B2, air %.3g kg/m\u00B3", preset.gravity, preset.airDensity);
        ImGui::SameLine();
    }
    ImGui::NewLine();
    // The scenery's world: automatic follows the gravity (levelTheme), or one named in the file.
    {
        const std::vector<WorldTheme> themes = allWorldThemes();
        std::vector<const char*> names{"automatic (from g)"};
        int current = 0;
        for (std::size_t i = 0; i < themes.size(); ++i)
        {
            names.push_back(worldThemeTitle(themes[i]));
            if (next.theme == themes[i])
                current = static_cast<int>(i) + 1;
        }
        if (ImGui::Combo("Scenery", &current, names.data(), static_cast<int>(names.size())))
        {
            if (current == 0)
                next.theme.reset();
            else
                next.theme = themes[static_cast<std::size_t>(current) - 1];
            setProperties(next, "Scenery", "");
        }
    }

    heading("Air");
    bool air = env.airDensity > 0.0;
    if (ImGui::Checkbox("Air resistance", &air))
    {
        if (air)
            env.airDensity = standardAtmosphereDensity(m_play.altitudeM);
        else
        {
            // Wind acts only through drag: without air there is none.
            env.airDensity = 0.0;
            env.windX = env.windY = 0.0;
            env.gusts.reset();
        }
        setProperties(next, air ? "Air on" : "Air off", "");
    }
    if (air)
    {
        if (sliderDouble("\u03C1 (kg/m\u00B3)", env.airDensity, 0.001, 10.0, "%.3f", ImGuiSliderFlags_Logarithmic))
            setProperties(next, "Air density", "air");
        endGestureIfReleased();
        if (sliderDouble("Altitude (m)", m_play.altitudeM, 0.0, 20000.0, "%.0f"))
        {
            // The U.S. Standard Atmosphere 1976 gives the density at that height, as PhET's altitude slider does.
            env.airDensity = standardAtmosphereDensity(m_play.altitudeM);
            setProperties(next, "Altitude", "air");
        }
        endGestureIfReleased();
        double wind[2] = {env.windX, env.windY};
        const double windMax = 30.0;
        const double windMin = -30.0;
        if (ImGui::SliderScalarN("Wind (m/s)", ImGuiDataType_Double, wind, 2, &windMin, &windMax, "%.1f"))
        {
            env.windX = wind[0];
            env.windY = wind[1];
            setProperties(next, "Wind", "wind");
        }
        endGestureIfReleased();
        int gustKind = !env.gusts ? 0 : env.gusts->kind == GustDef::Kind::Sine ? 1 : 2;
        const char* gustNames[] = {"No gusts", "Breathing (sine)", "Steps"};
        if (ImGui::Combo("Gusts", &gustKind, gustNames, 3))
        {
            if (gustKind == 0)
                env.gusts.reset();
            else if (gustKind == 1)
            {
                GustDef g;
                g.kind = GustDef::Kind::Sine;
                g.amplitudeX = 5.0;
                g.periodS = 3.0;
                env.gusts = g;
            }
            else
            {
                GustDef g;
                g.kind = GustDef::Kind::Steps;
                g.steps = {{1.0, -8.0, 0.0}, {2.0, 0.0, 0.0}};
                env.gusts = g;
            }
            setProperties(next, "Gusts", "");
        }
        if (env.gusts && env.gusts->kind == GustDef::Kind::Sine)
        {
            double amplitude[2] = {env.gusts->amplitudeX, env.gusts->amplitudeY};
            if (ImGui::SliderScalarN("Amplitude", ImGuiDataType_Double, amplitude, 2, &windMin, &windMax, "%.1f"))
            {
                env.gusts->amplitudeX = amplitude[0];
                env.gusts->amplitudeY = amplitude[1];
                setProperties(next, "Gust amplitude", "gust");
            }
            endGestureIfReleased();
            if (sliderDouble("Period (s)", env.gusts->periodS, 0.1, 30.0, "%.1f"))
                setProperties(next, "Gust period", "gust");
            endGestureIfReleased();
            double phaseDeg = env.gusts->phaseRad * 180.0 / 3.14159265358979323846;
            if (sliderDouble("Phase (\u00B0)", phaseDeg, -180.0, 180.0, "%.0f"))
            {
                env.gusts->phaseRad = phaseDeg * 3.14159265358979323846 / 180.0;
                setProperties(next, "Gust phase", "gust");
            }
            endGestureIfReleased();
        }
        else if (env.gusts)
        {
            ImGui::TextDisabled("From t (s after launch) the gust is (wx, wy):");
            for (std::size_t i = 0; i < env.gusts->steps.size(); ++i)
            {
                ImGui::PushID(static_cast<int>(i));
                double step[3] = {env.gusts->steps[i].startS, env.gusts->steps[i].windX, env.gusts->steps[i].windY};
                if (ImGui::InputScalarN("##step", ImGuiDataType_Double, step, 3, nullptr, nullptr, "%.1f",
                                        ImGuiInputTextFlags_EnterReturnsTrue))
                {
                    env.gusts->steps[i] = {step[0], step[1], step[2]};
                    setProperties(next, "Gust step", "");
                }
                ImGui::PopID();
            }
            if (ImGui::Button("Add step") && env.gusts->steps.size() < 100)
            {
                env.gusts->steps.push_back({env.gusts->steps.back().startS + 1.0, 0.0, 0.0});
                setProperties(next, "Add gust step", "");
            }
            ImGui::SameLine();
            if (ImGui::Button("Remove last") && env.gusts->steps.size() > 1)
            {
                env.gusts->steps.pop_back();
                setProperties(next, "Remove gust step", "");
            }
        }
    }
    ImGui::PopItemWidth();
    if (m_ctx.playing)
        ImGui::TextWrapped("Changes act at once, on the bird in flight too (its shot then gets no prediction score).");
}

void EditorInspector::birdTab()
{
    LevelDef next = m_ctx.scene().level();
    ImGui::PushItemWidth(-120.0f * m_ctx.app.ui().scale());
    if (m_ctx.playing)
    {
        // The world runs or stands still; the panels work either way.
        if (ImGui::Button(m_play.play().frozen() ? "Resume (P)" : "Pause (P)"))
            m_play.play().setFrozen(!m_play.play().frozen());
        ImGui::SameLine();
        if (ImGui::Button("Step 1/60 s") && m_play.play().frozen())
            m_play.play().stepOnce();
        heading("Launch");
        const double maxSpeed = m_play.play().maxSpeedMps();
        // The sliders show the aim however it was set (mouse, keys or these sliders).
        if (const auto aim = m_play.play().aim(); aim && !ImGui::IsAnyItemActive())
        {
            m_play.angleDeg = aim->angleDeg;
            m_play.speedMps = aim->speedMps;
        }
        bool aimChanged = sliderDouble("Angle (\u00B0)", m_play.angleDeg, -90.0, 90.0, "%.1f");
        m_play.speedMps = std::min(m_play.speedMps, maxSpeed);
        ImGui::Checkbox("Set the pull instead of the speed", &m_play.aimByPull);
        const auto band = m_play.play().session().band();
        if (m_play.aimByPull && band)
        {
            // The band stores E = 1/2 F x, shared by the bird and the band's moving mass.
            double pullM = band->forSpeed(m_play.speedMps).pullM;
            if (sliderDouble("Pull (m)", pullM, 0.0, band->maxPullM(), "%.2f"))
            {
                m_play.speedMps = band->atFraction(pullM / band->maxPullM()).speedMps;
                aimChanged = true;
            }
        }
        else
            aimChanged |= sliderDouble("Speed (m/s)", m_play.speedMps, 0.0, std::max(maxSpeed, 0.1), "%.2f");
        if (aimChanged)
            m_play.play().aimAt(m_play.angleDeg, m_play.speedMps);
        if (const auto aim = m_play.play().aim())
            ImGui::TextWrapped("%s\n%s", aimSummary(*aim).c_str(), aimLesson(*aim).c_str());
        if (ImGui::Button("Fire", ImVec2(-FLT_MIN, 0.0f)))
        {
            m_play.play().aimAt(m_play.angleDeg, m_play.speedMps);
            m_play.play().fire();
        }
        if (ImGui::Button("Play the scene again from the start (R)", ImVec2(-FLT_MIN, 0.0f)))
            m_play.play().restart();
        const GameSession& session = m_play.play().session();
        ImGui::Text("Birds left: %d", session.birdsRemaining());
        if (!m_ctx.message.empty())
            ImGui::TextWrapped("%s", m_ctx.message.c_str());
        if (session.finished())
            ImGui::TextWrapped("%s", session.phase() == Phase::Won
                                         ? "Every pig is down. R plays the scene again; Esc returns to editing."
                                         : "All birds are used. R plays the scene again; Esc returns to editing.");
    }

    // The birds list and the slingshot belong to the scene; the running copy keeps its own until it is played
    // again, so they are edited while the scene is not playing.
    if (!m_ctx.playing)
        birdListAndSlingshot(next);
    heading("Custom bird (PhET Lab's ranges)");
    bool custom = next.customBird.has_value();
    if (ImGui::Checkbox("Use a custom bird", &custom))
    {
        if (custom)
        {
            next.customBird = CustomBirdDef{};
            next.birds.insert(next.birds.begin(), kCustomBirdName);
            if (next.birds.size() > limits::kMaxBirds)
                next.birds.pop_back();
        }
        else
        {
            next.customBird.reset();
            std::erase(next.birds, std::string(kCustomBirdName));
            if (next.birds.empty())
                next.birds.push_back("red");
        }
        setProperties(next, custom ? "Custom bird" : "No custom bird", "");
    }
    if (next.customBird)
    {
        CustomBirdDef& bird = *next.customBird;
        bool changed = sliderDouble("Mass (kg)", bird.massKg, limits::kMinBirdMassKg, limits::kMaxBirdMassKg, "%.4g",
                                    ImGuiSliderFlags_Logarithmic);
        changed |= sliderDouble("Diameter (m)", bird.diameterM, limits::kMinBirdDiameterM, limits::kMaxBirdDiameterM,
                                "%.3g", ImGuiSliderFlags_Logarithmic);
        changed |= sliderDouble("Drag coeff. Cd", bird.dragCoefficient, limits::kMinDragCoefficient,
                                limits::kMaxDragCoefficient, "%.2f");
        if (changed)
            setProperties(next, "Custom bird", "custom-bird");
        endGestureIfReleased();
        // Say what the world does with it, here as well as when it is played.
        if (m_drawing.session())
        {
            const std::string text = describeBirdBody(
                m_drawing.session()->world().birdBody(customBirdType(*m_ctx.scene().level().customBird)));
            if (!text.empty())
                ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.3f, 1.0f), "%s",
                                   m_ctx.app.settings().universityWording() ? "Box2D:" : "Physics engine:");
            if (!text.empty())
                ImGui::TextWrapped("%s", text.c_str());
        }
    }
    ImGui::PopItemWidth();
}

void EditorInspector::birdListAndSlingshot(LevelDef& next)
{
    heading("Birds, in launch order");
    std::vector<std::string> names;
    for (const BirdType& bird : Catalog::builtin().birds())
        names.push_back(bird.name);
    if (next.customBird)
        names.emplace_back(kCustomBirdName);
    for (std::size_t i = 0; i < next.birds.size(); ++i)
    {
        ImGui::PushID(static_cast<int>(i));
        if (ImGui::BeginCombo("##bird", next.birds[i].c_str()))
        {
            for (const std::string& name : names)
                if (ImGui::Selectable(name.c_str(), name == next.birds[i]))
                {
                    next.birds[i] = name;
                    setProperties(next, "Bird", "");
                }
            ImGui::EndCombo();
        }
        ImGui::SameLine();
        if (ImGui::SmallButton("x") && next.birds.size() > 1)
        {
            next.birds.erase(next.birds.begin() + static_cast<std::ptrdiff_t>(i));
            setProperties(next, "Remove a bird", "");
            ImGui::PopID();
            break;
        }
        ImGui::PopID();
    }
    if (next.birds.size() < limits::kMaxBirds && ImGui::Button("Add a bird"))
    {
        next.birds.push_back(next.birds.back());
        setProperties(next, "Add a bird", "");
    }

    heading("Slingshot");
    // One band per world: a level without its own uses its world's, and follows it when the gravity changes.
    const BandDef band = levelBand(next, Catalog::builtin());
    bool own = next.slingshot.ownsBand();
    if (ImGui::Checkbox("Own band (check warns: each world has one)", &own))
    {
        SlingshotDef& sling = next.slingshot;
        sling.maxForceN = own ? std::optional(band.maxForceN) : std::nullopt;
        sling.maxPullM = own ? std::optional(band.maxPullM) : std::nullopt;
        sling.bandMassKg = own ? std::optional(band.bandMassKg) : std::nullopt;
        setProperties(next, own ? "Own band" : "World's band", "band");
    }
    if (!own)
        ImGui::TextWrapped("%s band: %.0f N at a %.1f m pull, %.0f kg moving with the bird",
                           worldThemeTitle(levelTheme(next)), band.maxForceN, band.maxPullM, band.bandMassKg);
    else
        ownBandSliders(next, band);
    endGestureIfReleased();
}

void EditorInspector::ownBandSliders(LevelDef& next, const BandDef& band)
{
    double force = band.maxForceN;
    if (sliderDouble("Force at full pull (N)", force, limits::kMinForceN, limits::kMaxForceN, "%.0f",
                     ImGuiSliderFlags_Logarithmic))
    {
        next.slingshot.maxForceN = force;
        setProperties(next, "Slingshot force", "force");
    }
    double pull = band.maxPullM;
    if (sliderDouble("Full pull (m)", pull, limits::kMinPullM, limits::kMaxPullM, "%.2f"))
    {
        next.slingshot.maxPullM = pull;
        setProperties(next, "Slingshot pull", "pull");
    }
    double mass = band.bandMassKg;
    if (sliderDouble("Band's moving mass (kg)", mass, 0.0, 100.0, "%.1f"))
    {
        next.slingshot.bandMassKg = mass;
        setProperties(next, "Band mass", "band mass");
    }
}

void EditorInspector::materialsTab()
{
    LevelDef next = m_ctx.scene().level();
    const Catalog scene = levelCatalog(next, Catalog::builtin());
    ImGui::TextWrapped("This scene's values; the catalog's are the defaults. Blocks already in the air keep "
                       "theirs until the scene is played again.");
    ImGui::PushItemWidth(-150.0f * m_ctx.app.ui().scale());
    for (const Material& base : Catalog::builtin().materials())
    {
        ImGui::PushID(base.name.c_str());
        heading(base.name.c_str());
        auto it = std::find_if(next.materials.begin(), next.materials.end(),
                               [&](const MaterialOverrideDef& m) { return m.material == base.name; });
        const Material& current = *scene.findMaterial(base.name);
        double density = current.bulkDensityKgPerM3;
        double friction = current.friction;
        double restitution = current.restitution;
        double strength = current.strengthNs;
        bool changed = false;
        const auto edit = [&](std::optional<double> MaterialOverrideDef::*field, double value)
        {
            if (it == next.materials.end())
            {
                next.materials.push_back({base.name, {}, {}, {}, {}});
                it = next.materials.end() - 1;
            }
            (*it).*field = value;
            changed = true;
        };
        if (sliderDouble("Density (kg/m\u00B3)", density, limits::kMinMaterialDensity, limits::kMaxMaterialDensity,
                         "%.0f", ImGuiSliderFlags_Logarithmic))
            edit(&MaterialOverrideDef::densityKgPerM3, density);
        endGestureIfReleased();
        if (sliderDouble("Friction \u03BC", friction, 0.0, limits::kMaxFriction, "%.2f"))
            edit(&MaterialOverrideDef::friction, friction);
        endGestureIfReleased();
        if (sliderDouble("Restitution e", restitution, 0.0, 1.0, "%.2f"))
            edit(&MaterialOverrideDef::restitution, restitution);
        endGestureIfReleased();
        if (sliderDouble("Strength (N s)", strength, limits::kMinStrengthNs, limits::kMaxStrengthNs, "%.0f",
                         ImGuiSliderFlags_Logarithmic))
            edit(&MaterialOverrideDef::strengthNs, strength);
        endGestureIfReleased();
        if (changed)
            setProperties(next, "Material", ("material-" + base.name).c_str());
        if (it != next.materials.end() && ImGui::Button("Back to the catalog's values"))
        {
            next.materials.erase(it);
            setProperties(next, "Reset material", "");
        }
        ImGui::PopID();
    }
    ImGui::PopItemWidth();
}

void EditorInspector::levelTab()
{
    LevelDef next = m_ctx.scene().level();
    ImGui::PushItemWidth(-110.0f * m_ctx.app.ui().scale());
    const auto text = [&](const char* label, std::string& value, const char* undo, bool multiline = false)
    {
        // ImGui edits a buffer of ours; it follows the scene while the field is idle and is applied when let go.
        const ImGuiID id = ImGui::GetID(label);
        std::string& buffer = m_textFields[id];
        if (ImGui::GetActiveID() != id)
            buffer = value;
        if (multiline)
            ImGui::InputTextMultiline(label, &buffer, ImVec2(-FLT_MIN, 3.5f * ImGui::GetTextLineHeight()));
        else
            ImGui::InputText(label, &buffer);
        if (ImGui::IsItemDeactivatedAfterEdit() && buffer != value)
        {
            value = buffer;
            setProperties(next, undo, "");
        }
    };
    text("Id", next.id, "Level id");
    text("Title", next.title, "Title");
    text("Episode", next.episode, "Episode");
    ImGui::TextUnformatted("Concept (the physics it teaches)");
    text("##concept", next.lesson, "Concept", true);
    heading("Hints");
    for (std::size_t i = 0; i < next.hints.size(); ++i)
    {
        ImGui::PushID(static_cast<int>(i));
        text("##hint", next.hints[i], "Hint");
        ImGui::SameLine();
        if (ImGui::SmallButton("x"))
        {
            next.hints.erase(next.hints.begin() + static_cast<std::ptrdiff_t>(i));
            setProperties(next, "Remove a hint", "");
            ImGui::PopID();
            break;
        }
        ImGui::PopID();
    }
    if (next.hints.size() < limits::kMaxHints && ImGui::Button("Add a hint"))
    {
        next.hints.emplace_back("A hint for the player.");
        setProperties(next, "Add a hint", "");
    }
    heading("Scoring");
    int stars[3] = {next.starScores[0], next.starScores[1], next.starScores[2]};
    if (ImGui::InputInt3("Stars at", stars, ImGuiInputTextFlags_EnterReturnsTrue))
    {
        next.starScores = {stars[0], stars[1], stars[2]};
        setProperties(next, "Star scores", "");
    }
    bool limited = next.timeLimitS.has_value();
    if (ImGui::Checkbox("Time limit", &limited))
    {
        next.timeLimitS = limited ? std::optional<double>(60.0) : std::nullopt;
        setProperties(next, "Time limit", "");
    }
    if (next.timeLimitS)
    {
        double limit = *next.timeLimitS;
        if (sliderDouble("Seconds", limit, 1.0, 600.0, "%.0f"))
        {
            next.timeLimitS = limit;
            setProperties(next, "Time limit", "time-limit");
        }
        endGestureIfReleased();
    }
    bool reference = next.referenceShot.has_value();
    if (ImGui::Checkbox("Reference shot", &reference))
    {
        next.referenceShot = reference ? std::optional<ReferenceShotDef>(ReferenceShotDef{45.0, 10.0}) : std::nullopt;
        setProperties(next, "Reference shot", "");
    }
    if (next.referenceShot)
    {
        double shot[2] = {next.referenceShot->angleDeg, next.referenceShot->speedMps};
        if (ImGui::InputScalarN("Angle, speed", ImGuiDataType_Double, shot, 2, nullptr, nullptr, "%.1f",
                                ImGuiInputTextFlags_EnterReturnsTrue))
        {
            next.referenceShot = ReferenceShotDef{shot[0], shot[1]};
            setProperties(next, "Reference shot", "");
        }
    }
    heading("Scene");
    if (ImGui::Checkbox("Sandbox scene (may have no pig)", &next.sandbox))
        setProperties(next, next.sandbox ? "Sandbox scene" : "Campaign level", "");
    double ground = next.groundY;
    if (inputDouble("Ground y (m)", ground, m_ctx.fieldReleased))
    {
        next.groundY = cleanMetres(ground);
        setProperties(next, "Ground", "");
    }
    ImGui::PopItemWidth();
}

void EditorInspector::checksTab()
{
    ImGui::TextWrapped("Findings are outlined in red on their objects; hover one for what was found.");
    if (ImGui::Button("Geometry and reach", ImVec2(-FLT_MIN, 0.0f)))
        m_ctx.checks.runGeometry(m_ctx.scene().level(), m_ctx.scene().revision());
    if (ImGui::Button("Rest test (10 s)", ImVec2(-FLT_MIN, 0.0f)))
        m_ctx.checks.runRest(m_ctx.scene().level(), m_ctx.scene().revision());
    if (m_ctx.checks.solving())
        ImGui::ProgressBar(m_ctx.checks.solverProgress(), ImVec2(-FLT_MIN, 0.0f), "solving...");
    else if (m_ctx.scene().level().pigs.empty())
        ImGui::TextDisabled("Solve: place a pig first");
    else if (ImGui::Button("Solve", ImVec2(-FLT_MIN, 0.0f)))
        m_ctx.checks.startSolver(m_ctx.scene().level(), m_ctx.scene().revision());
    ImGui::Separator();
    for (const std::string& summary : m_ctx.checks.summaries())
        ImGui::TextWrapped("%s", summary.c_str());
    ImGui::Separator();
    int id = 0;
    for (const Finding& finding : m_ctx.checks.findings())
    {
        ImGui::PushID(id++);
        const std::string where =
            finding.object ? describe(m_ctx.scene().level(), *finding.object) : std::string("the level");
        // The object's name selects it; what was found wraps under it.
        if (ImGui::Selectable(where.c_str(), finding.object && m_ctx.scene().isSelected(*finding.object)) &&
            finding.object && exists(m_ctx.scene().level(), *finding.object))
            m_ctx.scene().select(*finding.object);
        ImGui::Indent();
        ImGui::TextWrapped("%s", readablePointers(m_ctx.scene().level(), finding.message).c_str());
        ImGui::Unindent();
        ImGui::PopID();
    }
    const std::vector<LevelIssue> problems = m_ctx.scene().saveProblems();
    if (!problems.empty())
    {
        ImGui::Separator();
        ImGui::TextColored(ImVec4(1.0f, 0.55f, 0.45f, 1.0f), "Cannot be saved as a level yet:");
        for (const LevelIssue& issue : problems)
            ImGui::BulletText("%s", issue.message.c_str());
    }
}

void EditorInspector::multiSelectionFields(const std::vector<ObjectRef>& selection)
{
    // The blocks' common fields, shown with the first block's value and set on every selected block at once.
    std::vector<ObjectRef> blocks;
    for (const ObjectRef& ref : selection)
        if (ref.kind == ObjectKind::Block)
            blocks.push_back(ref);
    if (blocks.empty())
        return;
    // The blocks' common fields: a value they share is shown as it is, one where they differ as "mixed", and a field
    // changes every selected block only when it is set.
    std::vector<BlockDef> defs;
    for (const ObjectRef& ref : blocks)
        defs.push_back(std::get<BlockDef>(objectDef(m_ctx.scene().level(), ref)));
    BlockDef first = defs.front();
    ImGui::TextDisabled("For all %zu selected blocks:", blocks.size());
    ImGui::PushItemWidth(-110.0f * m_ctx.app.ui().scale());
    const auto applyToAll = [&](const char* label, const auto& change)
    {
        std::vector<ObjectDef> defs;
        for (const ObjectRef& ref : blocks)
        {
            BlockDef block = std::get<BlockDef>(objectDef(m_ctx.scene().level(), ref));
            change(block);
            defs.emplace_back(block);
        }
        const std::string why = m_ctx.scene().changeObjects(blocks, defs, label, std::string("multi-") + label);
        if (!why.empty())
        {
            m_ctx.message = why;
            m_ctx.messageIsError = true;
        }
    };
    std::vector<std::string> materials;
    for (const Material& material : Catalog::builtin().materials())
        materials.push_back(material.name);
    if (std::string name;
        mixedNameCombo("Material", sharedValue(defs, [](const BlockDef& b) { return b.material; }), materials, name))
        applyToAll("Material", [&](BlockDef& b) { b.material = name; });
    if (mixedNumberField("Width (m)", sharedValue(defs, [](const BlockDef& b) { return b.widthM; }), first.widthM,
                         m_ctx.fieldReleased))
        applyToAll("Width", [&](BlockDef& b) { b.widthM = first.widthM; });
    if (mixedNumberField("Height (m)", sharedValue(defs, [](const BlockDef& b) { return b.heightM; }), first.heightM,
                         m_ctx.fieldReleased))
        applyToAll("Height",
                   [&](BlockDef& b) { b.heightM = b.shape == BlockShape::Circle ? b.widthM : first.heightM; });
    if (mixedNumberField("Angle (\u00B0)", sharedValue(defs, [](const BlockDef& b) { return b.angleDeg; }),
                         first.angleDeg, m_ctx.fieldReleased, "%.1f"))
        applyToAll("Angle", [&](BlockDef& b) { b.angleDeg = first.angleDeg; });
    ImGui::PopItemWidth();
}

} // namespace abalike::app
