#include "save/ReadFile.hpp"
#include "save/SaveJson.hpp"

#include <abalike/save/AtomicWrite.hpp>
#include <abalike/save/SaveError.hpp>
#include <abalike/save/SaveStore.hpp>
#include <cerrno>
#include <cstdio>
#include <ctime>
#include <fcntl.h>
#include <optional>
#include <system_error>
#include <utility>

namespace abalike
{

namespace
{

constexpr int kMaxBackupsPerSecond = 100;

/// UTC, sortable and safe in a file name: 20240131T235959Z.
std::string timestamp()
{
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y%m%dT%H%M%SZ", &utc);
    return text;
}

/// Renames from to to unless to exists; returns 0 or the errno.
int renameNoReplace(const std::filesystem::path& from, const std::filesystem::path& to)
{
    if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0)
        return 0;
    if (errno != EINVAL && errno != ENOSYS)
        return errno;
    // The file system cannot refuse to replace: check first (a race here only loses an older backup).
    std::error_code ec;
    if (std::filesystem::exists(to, ec))
        return EEXIST;
    return std::rename(from.c_str(), to.c_str()) == 0 ? 0 : errno;
}

/// Moves a damaged file out of the way as NAME.corrupt-TIMESTAMP[-N]; the new name, or the reason it failed.
std::optional<std::filesystem::path> setAside(const std::filesystem::path& path, std::string& why)
{
    const std::string base = path.string() + ".corrupt-" + timestamp();
    for (int i = 1; i <= kMaxBackupsPerSecond; ++i)
    {
        const std::filesystem::path backup = i == 1 ? base : base + "-" + std::to_string(i);
        const int error = renameNoReplace(path, backup);
        if (error == 0)
            return backup;
        if (error != EEXIST)
        {
            why = std::error_code(error, std::generic_category()).message();
            return std::nullopt;
        }
    }
    why = "too many backups with the same time stamp";
    return std::nullopt;
}

} // namespace

SaveStore::SaveStore(std::filesystem::path dir) : m_dir(std::move(dir)) {}

void SaveStore::load(Damaged damaged)
{
    if (m_dir.empty())
    {
        m_messages.push_back("No folder for saved games is known (set ABALIKE_DATA_DIR or HOME): progress and "
                             "settings will not be kept after the game closes.");
        return;
    }
    m_progress = loadFile(m_progressState, progressPath(), &parseProgress, damaged);
    m_settings = loadFile(m_settingsState, settingsPath(), &parseSettings, damaged);
}

template <class T>
T SaveStore::loadFile(FileState& state, const std::filesystem::path& path, T (*parse)(std::string_view),
                      Damaged damaged)
{
    state.keepOut = false;
    const ReadResult read = readSmallFile(path, kMaxSaveBytes);
    std::string problem;
    switch (read.status)
    {
    case ReadResult::Status::Missing:
        return T{};
    case ReadResult::Status::Unreadable:
        state.keepOut = true;
        m_messages.push_back("Cannot read the " + std::string(state.what) + " file " + path.string() + " (" +
                             read.error + "): using defaults, and the file is left untouched.");
        return T{};
    case ReadResult::Status::TooLarge:
        problem = "it is larger than " + std::to_string(kMaxSaveBytes) + " bytes";
        break;
    case ReadResult::Status::Read:
        try
        {
            return parse(read.text);
        }
        catch (const SaveFormatError& e)
        {
            problem = e.what();
        }
        break;
    }
    if (damaged == Damaged::LeaveAlone)
    {
        state.keepOut = true;
        m_messages.push_back("The " + std::string(state.what) + " file " + path.string() + " is damaged (" + problem +
                             "): this scripted run uses defaults and leaves the file untouched.");
        return T{};
    }
    std::string why;
    if (const auto backup = setAside(path, why))
        m_messages.push_back("The " + std::string(state.what) + " file " + path.string() + " is damaged (" + problem +
                             "): it was kept as " + backup->string() + " and " + state.what + " starts from defaults.");
    else
    {
        state.keepOut = true;
        m_messages.push_back("The " + std::string(state.what) + " file " + path.string() + " is damaged (" + problem +
                             ") and could not be set aside (" + why +
                             "): using defaults, and the file is left untouched.");
    }
    return T{};
}

bool SaveStore::saveProgress(Progress progress)
{
    m_progress = std::move(progress);
    return saveFile(m_progressState, progressPath(), progressToJson(m_progress));
}

void SaveStore::pinSettings(Settings settings)
{
    m_settings = std::move(settings);
    m_settingsPinned = true;
}

bool SaveStore::saveSettings(Settings settings)
{
    m_settings = settings;
    if (m_settingsPinned)
        return true;
    return saveFile(m_settingsState, settingsPath(), settingsToJson(m_settings));
}

bool SaveStore::saveFile(FileState& state, const std::filesystem::path& path, const std::string& text)
{
    std::string error;
    if (m_dir.empty())
        error = "no folder for saved games is known (set ABALIKE_DATA_DIR or HOME)";
    else if (state.keepOut)
        error = path.string() + " could not be read when the game started, so it is left untouched";
    else
    {
        std::error_code ec;
        std::filesystem::create_directories(m_dir, ec);
        if (ec)
            error = "cannot create the folder " + m_dir.string() + ": " + ec.message();
        else
        {
            try
            {
                writeFileAtomically(path, text);
            }
            catch (const SaveIoError& e)
            {
                error = e.what();
            }
        }
    }
    if (error.empty())
    {
        state.lastError.clear();
        return true;
    }
    // A read-only or full folder fails on every save; telling the player once per cause is enough.
    if (error != state.lastError)
        m_messages.push_back("Your " + std::string(state.what) + " was not saved: " + error +
                             ". The game goes on; it is kept until the game closes.");
    state.lastError = error;
    return false;
}

std::vector<std::string> SaveStore::takeMessages()
{
    return std::exchange(m_messages, {});
}

Settings readSettingsFile(const std::filesystem::path& path)
{
    const ReadResult read = readSmallFile(path, kMaxSaveBytes);
    switch (read.status)
    {
    case ReadResult::Status::Missing:
        throw SaveIoError(path.string() + ": no such file");
    case ReadResult::Status::Unreadable:
        throw SaveIoError(path.string() + ": cannot read it (" + read.error + ")");
    case ReadResult::Status::TooLarge:
        throw SaveFormatError(path.string() + ": larger than " + std::to_string(kMaxSaveBytes) +
                              " bytes; a settings file is a few hundred");
    case ReadResult::Status::Read:
        break;
    }
    try
    {
        return parseSettings(read.text);
    }
    catch (const SaveFormatError& e)
    {
        throw SaveFormatError(path.string() + ": " + e.what());
    }
}

} // namespace abalike
