#include "editor/EditorFiles.hpp"

#include "editor/EditorContext.hpp"
#include "editor/PlayTest.hpp"
#include "editor/SceneTools.hpp"

#include "shell/AppContext.hpp"
#include "shell/DataPaths.hpp"
#include "shell/Navigator.hpp"
#include "shell/RunControl.hpp"
#include "shell/Trace.hpp"
#include "shell/UiMetrics.hpp"

#include <abalike/edit/Autosave.hpp>
#include <abalike/save/DataDirectory.hpp>
#include <abalike/save/SaveError.hpp>
#include <algorithm>
#include <imgui.h>
#include <imgui_stdlib.h>
#include <iostream>

namespace abalike::app
{

namespace
{
/// Autosave at most this often while there are unsaved changes.
constexpr auto kAutosaveEvery = std::chrono::seconds(5);

} // namespace

EditorFiles::EditorFiles(EditorContext& context, PlayTest& play, SceneTools& tools)
    : m_ctx(context), m_play(play), m_tools(tools)
{
    // An unsaved scene from a run that ended without saving is offered back (never in scripted runs).
    if (m_ctx.app.run().scripted())
        return;
    const auto dir = defaultDataDirectory();
    try
    {
        if (auto saved = dir.empty() ? std::nullopt : readAutosave(autosavePath(dir), Catalog::builtin()))
        {
            EditorSource recovered;
            recovered.level = std::move(saved->level);
            recovered.path = saved->target;
            recovered.issues = std::move(saved->geometryIssues);
            m_recovered = std::move(recovered);
        }
    }
    catch (const LevelLoadError& error)
    {
        std::cerr << "abalike: " << error.what() << "\n";
    }
}

std::filesystem::path EditorFiles::schemaPath() const
{
    return std::filesystem::path(levelsDirectory()) / "schema" / "level.schema.json";
}

std::filesystem::path EditorFiles::defaultSavePath() const
{
    if (!m_ctx.scene().path().empty())
        return m_ctx.scene().path();
    // A new scene goes with the player's files, not into the game's own levels.
    const std::filesystem::path data = defaultDataDirectory();
    const std::string name =
        (m_ctx.scene().level().id.empty() ? std::string("scene") : m_ctx.scene().level().id) + ".json";
    return data.empty() ? std::filesystem::path(name) : data / "levels" / name;
}

void EditorFiles::requestSave()
{
    if (m_ctx.scene().path().empty())
        requestSaveAs();
    else
        saveTo(m_ctx.scene().path());
}

void EditorFiles::requestSaveAs()
{
    m_fileDialogSaves = true;
    m_fileDialogPath = defaultSavePath().string();
    m_showFileDialog = true;
}

bool EditorFiles::saveTo(const std::filesystem::path& path)
{
    try
    {
        std::error_code ec;
        if (path.has_parent_path() && !std::filesystem::exists(path.parent_path(), ec) &&
            path.parent_path() == defaultSavePath().parent_path())
            std::filesystem::create_directories(path.parent_path(), ec); // the player's own levels folder
        const std::vector<LevelIssue> geometry = m_ctx.scene().save(path, schemaPath());
        m_ctx.checks.setOpeningIssues({}, m_ctx.scene().revision());
        if (!geometry.empty())
            m_ctx.checks.runGeometry(m_ctx.scene().level(), m_ctx.scene().revision());
        // What `abalike check` will say about the file: its geometry problems and the rest test's findings (the
        // first in full, with its fix), the rest test run now if it has not seen this revision.
        m_ctx.checks.refreshRest(m_ctx.scene().level(), m_ctx.scene().revision());
        std::vector<std::string> rest;
        for (const Finding& finding : m_ctx.checks.findings())
            if (finding.source == FindingSource::Rest && finding.object &&
                finding.message.rfind("moves because ", 0) != 0)
                rest.push_back(finding.message);
        std::string problems;
        if (!geometry.empty())
            problems = std::to_string(geometry.size()) + " geometry problem(s)";
        if (!rest.empty())
            problems += (problems.empty() ? "" : ", ") + std::to_string(rest.size()) +
                        (rest.size() == 1 ? " body that does not stand: " : " bodies that do not stand, first: ") +
                        rest.front();
        m_ctx.message =
            "Saved " + path.string() +
            (problems.empty() ? std::string() : " (" + problems + "; marked: `abalike check` will fail it)");
        m_ctx.messageIsError = !problems.empty();
        m_ctx.app.trace().write("editor-save",
                                {{"path", path.string()}, {"problems", geometry.size()}, {"rest_findings", rest}});
        if (!m_ctx.app.run().scripted())
            removeAutosave(autosavePath(defaultDataDirectory()));
        return true;
    }
    catch (const LevelLoadError& error)
    {
        m_ctx.message = "Not saved: " + (error.issues().empty()
                                             ? std::string(error.what())
                                             : error.issues().front().pointer + ": " + error.issues().front().message);
    }
    catch (const std::exception& error)
    {
        m_ctx.message = std::string("Not saved: ") + error.what();
    }
    m_ctx.messageIsError = true;
    m_ctx.app.trace().write("editor-save-failed", {{"path", path.string()}, {"why", m_ctx.message}});
    return false;
}

void EditorFiles::request(Pending action)
{
    if (m_ctx.scene().dirty() && action != Pending::None)
    {
        m_pending = action;
        m_showUnsaved = true;
        return;
    }
    carryOut(action);
}

void EditorFiles::carryOut(Pending action)
{
    m_pending = Pending::None;
    switch (action)
    {
    case Pending::Leave:
        m_play.stop();
        m_ctx.app.navigator().screens().pop();
        break;
    case Pending::Quit:
        m_ctx.app.navigator().quit(0);
        break;
    case Pending::New:
        resetScene(sandboxSource());
        break;
    case Pending::Open:
        m_fileDialogSaves = false;
        m_fileDialogPath = m_ctx.scene().path().empty() ? levelsDirectory() + "/" : m_ctx.scene().path().string();
        m_showFileDialog = true;
        break;
    case Pending::None:
        break;
    }
}

void EditorFiles::resetScene(EditorSource source)
{
    m_play.stop();
    m_ctx.replaceScene(source);
    m_tools.reset();
    m_ctx.message = source.path.empty() ? "New sandbox scene" : "Opened " + source.path.string();
    m_ctx.messageIsError = false;
    m_ctx.app.trace().write("editor", {{"level", m_ctx.scene().level().id}, {"path", source.path.string()}});
}

void EditorFiles::openFile(const std::filesystem::path& path)
{
    // Open opens what is there; a new level starts from File > New or `abalike edit NEW.json`.
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
    {
        m_ctx.message = std::filesystem::exists(path, ec) ? "\"" + path.string() + "\" is a folder, not a level file"
                                                          : "No such file: \"" + path.string() + "\"";
        m_ctx.messageIsError = true;
        return;
    }
    try
    {
        resetScene(editorSourceFor(path));
        m_showFileDialog = false;
    }
    catch (const LevelLoadError& error)
    {
        m_ctx.message = error.issues().empty() ? error.what() : error.issues().front().format();
        m_ctx.messageIsError = true;
        for (const LevelIssue& issue : error.issues())
            std::cerr << issue.format() << "\n";
    }
}

void EditorFiles::autosaveIfDue()
{
    // Scripted runs never write the player's files.
    if (m_ctx.app.run().scripted())
        return;
    if (!m_ctx.scene().dirty())
    {
        // Undone back to what was saved: nothing is left to recover.
        if (m_autosaveWritten)
            removeAutosave(autosavePath(defaultDataDirectory()));
        m_autosaveWritten = false;
        return;
    }
    if (m_ctx.scene().revision() == m_autosavedRevision)
        return;
    const auto now = std::chrono::steady_clock::now();
    if (now - m_lastAutosave < kAutosaveEvery)
        return;
    m_lastAutosave = now;
    m_autosavedRevision = m_ctx.scene().revision();
    const std::filesystem::path dir = defaultDataDirectory();
    if (dir.empty())
        return;
    try
    {
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        writeAutosave(autosavePath(dir), m_ctx.scene().level(), m_ctx.scene().path(), Catalog::builtin());
        m_autosaveWritten = true;
    }
    catch (const std::exception& error)
    {
        m_ctx.message = std::string("Autosave failed: ") + error.what();
        m_ctx.messageIsError = true;
    }
}

void EditorFiles::dialogs()
{
    if (m_recovered && !ImGui::IsPopupOpen("Recover an unsaved scene"))
        ImGui::OpenPopup("Recover an unsaved scene");
    recoverDialog();
    if (m_showUnsaved && !ImGui::IsPopupOpen("Unsaved changes"))
        ImGui::OpenPopup("Unsaved changes");
    unsavedDialog();
    const char* fileTitle = m_fileDialogSaves ? "Save level as" : "Open a level";
    if (m_showFileDialog && !ImGui::IsPopupOpen(fileTitle))
        ImGui::OpenPopup(fileTitle);
    fileDialog();
    m_ctx.modalOpen = ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
}

void EditorFiles::recoverDialog()
{
    const ImVec2 centre(0.5f * static_cast<float>(m_ctx.app.ui().windowSize().x),
                        0.5f * static_cast<float>(m_ctx.app.ui().windowSize().y));
    ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal("Recover an unsaved scene", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
        return;
    const EditorSource& source = *m_recovered;
    ImGui::Text("The editor kept a scene that was never saved:");
    ImGui::BulletText("\"%s\", %zu blocks, %zu pigs", source.level.title.c_str(), source.level.blocks.size(),
                      source.level.pigs.size());
    ImGui::BulletText("it belongs to %s", source.path.empty() ? "no file yet" : source.path.string().c_str());
    if (ImGui::Button("Open it"))
    {
        EditorSource recovered = std::move(*m_recovered);
        m_recovered.reset();
        resetScene(std::move(recovered));
        m_ctx.scene().markUnsaved();
        m_ctx.message = "Recovered the unsaved scene; save it to keep it.";
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard it"))
    {
        m_recovered.reset();
        removeAutosave(autosavePath(defaultDataDirectory()));
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Not now"))
    {
        m_recovered.reset();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

void EditorFiles::unsavedDialog()
{
    const ImVec2 centre(0.5f * static_cast<float>(m_ctx.app.ui().windowSize().x),
                        0.5f * static_cast<float>(m_ctx.app.ui().windowSize().y));
    ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
        return;
    const std::string name = m_ctx.scene().path().empty() ? m_ctx.scene().level().title : m_ctx.scene().path().string();
    ImGui::Text("\"%s\" has changes that are not saved.", name.c_str());
    ImGui::TextDisabled("(An autosave keeps them in the data folder until you decide.)");
    if (ImGui::Button("Save"))
    {
        m_showUnsaved = false;
        ImGui::CloseCurrentPopup();
        if (m_ctx.scene().path().empty())
            requestSave(); // the save dialog carries on with the pending action once saved
        else if (saveTo(m_ctx.scene().path()))
            carryOut(m_pending);
        else
            m_pending = Pending::None;
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard changes"))
    {
        m_showUnsaved = false;
        ImGui::CloseCurrentPopup();
        if (!m_ctx.app.run().scripted())
            removeAutosave(autosavePath(defaultDataDirectory()));
        carryOut(m_pending);
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel"))
    {
        m_showUnsaved = false;
        m_pending = Pending::None;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

void EditorFiles::fileDialog()
{
    const char* title = m_fileDialogSaves ? "Save level as" : "Open a level";
    const sf::Vector2f window(m_ctx.app.ui().windowSize());
    ImGui::SetNextWindowPos(ImVec2(0.5f * window.x, 0.5f * window.y), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(window.x - 40.0f, 720.0f * m_ctx.app.ui().scale()), 0.0f),
                             ImGuiCond_Always);
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_NoResize))
        return;
    ImGui::TextUnformatted("File:");
    ImGui::PushItemWidth(-FLT_MIN);
    if (ImGui::IsWindowAppearing())
        ImGui::SetKeyboardFocusHere();
    const bool entered = ImGui::InputText("##path", &m_fileDialogPath, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::PopItemWidth();
    // Level files nearby: the file's own folder, the game's levels and the player's.
    std::vector<std::filesystem::path> folders{std::filesystem::path(m_fileDialogPath).parent_path(), levelsDirectory(),
                                               defaultSavePath().parent_path()};
    std::sort(folders.begin(), folders.end());
    folders.erase(std::unique(folders.begin(), folders.end()), folders.end());
    ImGui::BeginChild("files", ImVec2(0.0f, 9.0f * ImGui::GetTextLineHeightWithSpacing()), true);
    for (const std::filesystem::path& folder : folders)
        for (const std::filesystem::path& file : levelFilesForDialogs(folder))
            if (ImGui::Selectable(file.string().c_str(), file.string() == m_fileDialogPath,
                                  ImGuiSelectableFlags_AllowDoubleClick))
            {
                m_fileDialogPath = file.string();
                if (ImGui::IsMouseDoubleClicked(0) && !m_fileDialogSaves)
                    openFile(file);
            }
    ImGui::EndChild();
    if (m_ctx.messageIsError && !m_ctx.message.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.55f, 0.45f, 1.0f), "%s", m_ctx.message.c_str());
    const bool go = ImGui::Button(m_fileDialogSaves ? "Save" : "Open") || entered;
    ImGui::SameLine();
    if (ImGui::Button("Cancel"))
    {
        m_showFileDialog = false;
        m_pending = Pending::None;
        ImGui::CloseCurrentPopup();
    }
    else if (go && !m_fileDialogPath.empty())
    {
        if (!m_fileDialogSaves)
            openFile(m_fileDialogPath);
        else if (saveTo(m_fileDialogPath))
        {
            m_showFileDialog = false;
            carryOut(m_pending); // Save from the unsaved-changes prompt: now do what was asked
        }
        if (!m_showFileDialog)
            ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

} // namespace abalike::app
