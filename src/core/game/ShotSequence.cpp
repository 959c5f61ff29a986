#include <abalike/game/ShotSequence.hpp>

#include <algorithm>
#include <string>
#include <utility>

namespace abalike
{

ShotSequence::ShotSequence(std::vector<ScriptedShot> shots, double holdS, std::size_t alreadyFired)
    : m_shots(std::move(shots)), m_holdS(holdS), m_next(std::min(alreadyFired, m_shots.size()))
{
}

ShotSequence::Tick ShotSequence::advance(GameSession& session, double dtS)
{
    m_firedNow = false;
    const bool underWay = session.phase() == Phase::Flying || session.winPending();
    if (!underWay)
    {
        if (session.finished() || pending() == nullptr)
            return Tick::Idle;
        m_heldS += dtS;
        if (m_heldS < m_holdS - 1e-9)
            return Tick::Held;
        fire(session);
    }
    // A bird that can no longer use its ability by then (it already touched something) simply flies on.
    if (m_abilityAtS && session.timeSinceLaunch() >= *m_abilityAtS - 1e-9)
    {
        session.activateAbility();
        m_abilityAtS.reset();
    }
    session.step();
    return Tick::Stepped;
}

void ShotSequence::fire(GameSession& session)
{
    const std::size_t number = m_next + 1;
    try
    {
        session.launch(m_shots[m_next]);
    }
    catch (const LaunchError& e)
    {
        throw LaunchError("shot " + std::to_string(number) + ": " + e.what());
    }
    m_abilityAtS = m_shots[m_next].abilityAtS;
    ++m_next;
    m_heldS = 0.0;
    m_firedNow = true;
}

} // namespace abalike
