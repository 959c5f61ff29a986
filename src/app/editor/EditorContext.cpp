#include "editor/EditorContext.hpp"

#include <abalike/edit/Landing.hpp>

#include "shell/AppContext.hpp"
#include "shell/UiMetrics.hpp"

#include <algorithm>
#include <imgui.h>

namespace abalike::app
{

EditorContext::EditorContext(AppContext& owner, const EditorSource& source)
    : app(owner), editor(std::make_unique<SceneEditor>(source.level))
{
    editor->setPath(source.path);
    checks.setOpeningIssues(source.issues, editor->revision());
}

void EditorContext::replaceScene(const EditorSource& source)
{
    editor = std::make_unique<SceneEditor>(source.level);
    editor->setPath(source.path);
    checks.clear();
    checks.setOpeningIssues(source.issues, editor->revision());
    ++sceneGeneration;
    viewFitted = false;
}

void EditorContext::undo()
{
    scene().undo();
    if (messageIsError)
        say("");
}

void EditorContext::redo()
{
    scene().redo();
    if (messageIsError)
        say("");
}

bool EditorContext::sayIfNotLanded()
{
    const SnapSettings& snap = scene().snapSettings();
    const std::optional<std::string> why =
        whyNotLanded(scene().level(), scene().catalog(), scene().selection(), snap.surfaces ? snap.surfaceReachM : 0.0);
    if (why)
        say(*why, true);
    return why.has_value();
}

void EditorContext::say(std::string text, bool error)
{
    message = std::move(text);
    messageIsError = error;
}

sf::FloatRect EditorContext::sceneArea() const
{
    const sf::Vector2f size(app.ui().windowSize());
    const float scale = app.ui().scale();
    // The menu bar and the status bar: a line of 16 px text with ImGui's frame and window padding.
    const float top = 22.0f * scale;
    const float bottom = playing ? 0.0f : std::max(38.0f * scale, statusBarHeight);
    const float left = playing ? 0.0f : 220.0f * scale;
    const float right = 350.0f * scale;
    return {left, top, std::max(50.0f, size.x - left - right), std::max(50.0f, size.y - top - bottom)};
}

float EditorContext::statusBarHeightNow() const
{
    return std::max(ImGui::GetFrameHeight() + 2.0f * ImGui::GetStyle().WindowPadding.y, statusBarHeight);
}

void EditorContext::recordPanel()
{
    const ImVec2 pos = ImGui::GetWindowPos();
    const ImVec2 size = ImGui::GetWindowSize();
    panels.emplace_back(pos.x, pos.y, size.x, size.y);
}

bool EditorContext::pointerOverPanels(sf::Vector2f pixel) const
{
    for (const sf::FloatRect& panel : panels)
        if (panel.contains(pixel))
            return true;
    return false;
}

void EditorContext::fitView()
{
    view.fit(scene().level(), Catalog::builtin(), sceneArea(), app.ui().windowSize());
    viewFitted = true;
}

} // namespace abalike::app
