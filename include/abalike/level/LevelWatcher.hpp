#pragma once

#include <abalike/level/LevelIO.hpp>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace abalike
{

/// Watches a level file for live reload. It polls the file's modification time and size (no platform file
/// events needed) and reloads once a change has held still for one poll interval, so an editor's half-written
/// save is not read. A reload that fails reports its problems; the caller keeps playing the last good level.
class LevelWatcher
{
public:
    using Clock = std::chrono::steady_clock;

    /// What a reload found: the new level, or every problem with the file.
    struct Reload
    {
        std::optional<LevelDef> level;
        std::vector<LevelIssue> issues;
    };

    /// Starts watching; the file as it is now counts as already loaded.
    LevelWatcher(std::string path, const Catalog& catalog,
                 std::chrono::milliseconds interval = std::chrono::milliseconds(250));

    /// Looks at the file if an interval has passed since the last look; a reload once a change has settled.
    std::optional<Reload> poll(Clock::time_point now = Clock::now());

    const std::string& path() const { return m_path; }

private:
    struct Stamp
    {
        std::filesystem::file_time_type modified{};
        std::uintmax_t size = 0;
        bool operator==(const Stamp&) const = default;
    };

    std::optional<Stamp> stamp() const;

    std::string m_path;
    const Catalog& m_catalog;
    std::chrono::milliseconds m_interval;
    Clock::time_point m_lastPoll{};
    std::optional<Stamp> m_loaded;  ///< what the last reload (or the start) saw
    std::optional<Stamp> m_pending; ///< a change seen at the last poll, reloaded when it is still the same
};

} // namespace abalike
