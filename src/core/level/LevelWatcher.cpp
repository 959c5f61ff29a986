#include <abalike/level/LevelWatcher.hpp>

namespace abalike
{

LevelWatcher::LevelWatcher(std::string path, const Catalog& catalog, std::chrono::milliseconds interval)
    : m_path(std::move(path)), m_catalog(catalog), m_interval(interval), m_loaded(stamp())
{
}

std::optional<LevelWatcher::Stamp> LevelWatcher::stamp() const
{
    std::error_code ec;
    const auto modified = std::filesystem::last_write_time(m_path, ec);
    if (ec)
        return std::nullopt;
    const auto size = std::filesystem::file_size(m_path, ec);
    if (ec)
        return std::nullopt;
    return Stamp{modified, size};
}

std::optional<LevelWatcher::Reload> LevelWatcher::poll(Clock::time_point now)
{
    if (now - m_lastPoll < m_interval)
        return std::nullopt;
    m_lastPoll = now;
    const std::optional<Stamp> current = stamp();
    // Missing for a moment: editors that save by renaming a new file over the old one.
    if (!current || current == m_loaded)
    {
        m_pending.reset();
        return std::nullopt;
    }
    if (current != m_pending)
    {
        m_pending = current; // changed since the last look: wait until the writer is done
        return std::nullopt;
    }
    m_pending.reset();
    m_loaded = current;
    Reload reload;
    try
    {
        reload.level = loadLevel(m_path, m_catalog);
    }
    catch (const LevelLoadError& e)
    {
        reload.issues = e.issues();
    }
    return reload;
}

} // namespace abalike
