#include <abalike/game/SessionBranch.hpp>
#include <abalike/game/ShotSequence.hpp>
#include <abalike/util/ProcessCopy.hpp>

#include <chrono>
#include <optional>
#include <utility>

namespace abalike
{

namespace
{

/// Plays the shots of the list from `fired` on, each to the end of its turn.
void playFrom(GameSession& session, const std::vector<ScriptedShot>& shots, std::size_t fired)
{
    ShotSequence sequence(shots, 0.0, fired);
    while (sequence.advance(session, session.world().dt()) != ShotSequence::Tick::Idle)
    {
    }
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A trial's bytes start with what became of it: read's bytes follow, or the LaunchError's message.
constexpr char kRead = 'r';
constexpr char kRefused = 'x';

} // namespace

SessionBranch::SessionBranch(const LevelDef& level, std::vector<ScriptedShot> shots, const Catalog& catalog)
    : m_level(level), m_catalog(catalog), m_shots(std::move(shots))
{
    if (m_shots.size() > level.birds.size())
        throw LaunchError("shot " + std::to_string(level.birds.size() + 1) +
                          ": no bird left to launch (the level has " + std::to_string(level.birds.size()) + ")");
    m_session = std::make_unique<GameSession>(level, catalog);
    playFrom(*m_session, m_shots, 0);
}

void SessionBranch::play(const ScriptedShot& shot)
{
    if (m_shots.size() >= m_level.birds.size())
        throw LaunchError("shot " + std::to_string(m_shots.size() + 1) + ": no bird left to launch (the level has " +
                          std::to_string(m_level.birds.size()) + ")");
    m_shots.push_back(shot);
    playFrom(*m_session, m_shots, m_shots.size() - 1);
}

std::string SessionBranch::trial(const ScriptedShot& shot, const Read& read) const
{
    std::vector<ScriptedShot> shots = m_shots;
    shots.push_back(shot);
    const auto start = std::chrono::steady_clock::now();
    if (!m_costs.copyNext(!m_shots.empty() && processCopiesAvailable()))
    {
        std::string bytes = read(*simulateShots(m_level, shots, m_catalog));
        m_costs.addReplay(secondsSince(start));
        return bytes;
    }
    const std::optional<std::string> copied = runInProcessCopy(
        [&]() -> std::string
        {
            // The copy's own session: changing it changes nothing in this process.
            GameSession& session = *m_session;
            try
            {
                playFrom(session, shots, m_shots.size());
            }
            catch (const LaunchError& e)
            {
                return kRefused + std::string(e.what());
            }
            return kRead + read(session);
        });
    if (copied && !copied->empty())
    {
        m_costs.addCopy(secondsSince(start));
        if (copied->front() == kRefused)
            throw LaunchError(copied->substr(1));
        return copied->substr(1);
    }
    return read(*simulateShots(m_level, shots, m_catalog));
}

bool SessionBranch::TrialCosts::copyNext(bool canCopy)
{
    if (!canCopy)
        return false;
    const std::lock_guard lock(m_mutex);
    // A few of each way first; then the way that has been quicker on this branch.
    if (m_copies < kTries)
        return true;
    if (m_replays < kTries)
        return false;
    return m_copyS / m_copies < m_replayS / m_replays;
}

void SessionBranch::TrialCosts::addCopy(double seconds)
{
    const std::lock_guard lock(m_mutex);
    m_copyS += seconds;
    ++m_copies;
}

void SessionBranch::TrialCosts::addReplay(double seconds)
{
    const std::lock_guard lock(m_mutex);
    m_replayS += seconds;
    ++m_replays;
}

} // namespace abalike
