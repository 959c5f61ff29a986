#pragma once

#include <abalike/game/GameSession.hpp>
#include <cstddef>
#include <utility>
#include <vector>

namespace abalike::app
{

/// Scripted shots (`--shot`): each waits in the slingshot, its preview showing, for a moment of game time,
/// then fires. Timing is in game time, so offline runs (`--frames`) are reproducible.
class ShotScript
{
public:
    explicit ShotScript(std::vector<ScriptedShot> shots, double holdS = 0.5) : m_shots(std::move(shots)), m_holdS(holdS)
    {
    }

    /// The next shot not yet fired, or null.
    const ScriptedShot* pending() const { return m_next < m_shots.size() ? &m_shots[m_next] : nullptr; }
    /// Counts one fixed step of showing the pending shot; true once it has been shown long enough.
    bool tick(double dtS)
    {
        m_shownS += dtS;
        return pending() != nullptr && m_shownS >= m_holdS - 1e-9;
    }
    /// The pending shot was fired; the next one starts its wait.
    void advance()
    {
        ++m_next;
        m_shownS = 0.0;
    }

private:
    std::vector<ScriptedShot> m_shots;
    double m_holdS;
    std::size_t m_next = 0;
    double m_shownS = 0.0;
};

} // namespace abalike::app
