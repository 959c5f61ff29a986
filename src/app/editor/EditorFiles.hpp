#pragma once

#include "editor/EditorSource.hpp"

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

namespace abalike::app
{

struct EditorContext;
class PlayTest;
class SceneTools;

/// The editor's files: save (atomic, with a $schema path right for where it is saved), save as, open, new, the
/// prompt before unsaved changes are dropped, autosave to the data directory, and the offer of a scene a run left
/// unsaved.
class EditorFiles
{
public:
    /// What the designer asked for that may drop unsaved changes.
    enum class Pending
    {
        None,
        Leave, ///< leave the editor (Esc, File > Close)
        Quit,  ///< the window is closing
        New,   ///< start a new sandbox scene
        Open,  ///< open another file
    };

    EditorFiles(EditorContext& context, PlayTest& play, SceneTools& tools);

    /// Saves to the scene's file, or asks where when it has none.
    void requestSave();
    /// Asks where to save (File > Save as, Ctrl+Shift+S).
    void requestSaveAs();
    /// Does it, after asking to save when the scene has unsaved changes.
    void request(Pending action);
    void autosaveIfDue();
    /// The open, save-as, unsaved-changes and recovery dialogs (Dear ImGui popups), while one is up.
    void dialogs();

private:
    bool saveTo(const std::filesystem::path& path);
    void carryOut(Pending action);
    void openFile(const std::filesystem::path& path);
    void resetScene(EditorSource source);
    void fileDialog();
    void unsavedDialog();
    void recoverDialog();
    std::filesystem::path schemaPath() const;
    std::filesystem::path defaultSavePath() const;

    EditorContext& m_ctx;
    PlayTest& m_play;
    SceneTools& m_tools;
    Pending m_pending = Pending::None;
    bool m_showUnsaved = false;
    bool m_showFileDialog = false;
    bool m_fileDialogSaves = false;
    std::string m_fileDialogPath;
    std::optional<EditorSource> m_recovered;
    std::uint64_t m_autosavedRevision = 0;
    bool m_autosaveWritten = false;
    std::chrono::steady_clock::time_point m_lastAutosave = std::chrono::steady_clock::now();
};

} // namespace abalike::app
