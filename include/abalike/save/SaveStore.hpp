#pragma once

#include <abalike/save/Progress.hpp>
#include <abalike/save/Settings.hpp>
#include <filesystem>
#include <string>
#include <vector>

namespace abalike
{

/// The player's progress and settings on disk. Never throws and never loses the player's files: a damaged file is
/// renamed to NAME.corrupt-TIMESTAMP and defaults are used, a file that cannot be read is left alone and never
/// overwritten, and a folder that cannot be written (read-only, full) only means the game goes on without saving.
/// Everything the player should know is collected as messages.
class SaveStore
{
public:
    /// Files live in dir, which is created on the first save; an empty dir means nothing is ever saved.
    explicit SaveStore(std::filesystem::path dir);

    /// What load() does with a damaged file.
    enum class Damaged
    {
        SetAside,   ///< rename it to NAME.corrupt-TIMESTAMP, so the next save starts a fresh file (a player's run)
        LeaveAlone, ///< touch nothing and never overwrite it: scripted runs, which must not write the data folder
    };

    /// Reads progress.json and settings.json; missing files give defaults without a message.
    void load(Damaged damaged = Damaged::SetAside);

    const Progress& progress() const { return m_progress; }
    const Settings& settings() const { return m_settings; }

    /// Uses settings read from another file (`--settings FILE`) instead of settings.json for this run: changes are
    /// kept in memory and never written, so neither that file nor the player's settings change.
    void pinSettings(Settings settings);
    bool settingsPinned() const { return m_settingsPinned; }

    /// Keeps progress in memory and writes it atomically; false (and a message) when it could not be written.
    bool saveProgress(Progress progress);
    /// Keeps settings in memory and writes them atomically; false (and a message) when they could not be written.
    bool saveSettings(Settings settings);

    /// What the player should be told since the last call, one sentence each.
    std::vector<std::string> takeMessages();

    const std::filesystem::path& directory() const { return m_dir; }
    std::filesystem::path progressPath() const { return m_dir / "progress.json"; }
    std::filesystem::path settingsPath() const { return m_dir / "settings.json"; }

private:
    /// What the store knows about one of its files.
    struct FileState
    {
        const char* what;      ///< "progress" or "settings", for messages
        bool keepOut = false;  ///< the file exists but could not be read or set aside: never overwrite it
        std::string lastError; ///< the last write failure, so a repeated failure is reported once
    };

    template <class T>
    T loadFile(FileState& state, const std::filesystem::path& path, T (*parse)(std::string_view), Damaged damaged);
    bool saveFile(FileState& state, const std::filesystem::path& path, const std::string& text);

    std::filesystem::path m_dir;
    Progress m_progress;
    Settings m_settings;
    FileState m_progressState{"progress", false, {}};
    FileState m_settingsState{"settings", false, {}};
    std::vector<std::string> m_messages;
    bool m_settingsPinned = false;
};

/// Reads a settings file given by name (`--settings FILE`). Throws SaveIoError or SaveFormatError with a message
/// that names the file and what is wrong in it.
Settings readSettingsFile(const std::filesystem::path& path);

} // namespace abalike
