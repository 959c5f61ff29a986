#pragma once

#include <abalike/game/GameSession.hpp>
#include <cstddef>
#include <optional>
#include <vector>

namespace abalike
{

/// Scripted shots played on a session one fixed step at a time: the one timing `abalike simulate` and
/// `abalike play --shot` share. Each shot fires as soon as its bird is ready, from the world as it is then; its
/// ability fires at the first step boundary at or after its time. A hold (the window shows the pending shot's
/// preview for a moment) counts steps of game time without stepping the world, so it changes nothing that
/// happens.
class ShotSequence
{
public:
    /// What one call of advance() did.
    enum class Tick
    {
        Held,    ///< a shot waits out its hold; the world did not move
        Stepped, ///< the world took one step (a shot may have fired first: fired() says which)
        Idle,    ///< no shot is left to fire and none is under way; the caller steps the world if it goes on
    };

    /// alreadyFired: the first shots of the list were fired before on this session (a SessionBranch goes on
    /// from them), so the sequence starts at the next and numbers its shots as the whole list does.
    explicit ShotSequence(std::vector<ScriptedShot> shots, double holdS = 0.0, std::size_t alreadyFired = 0);

    /// One fixed step of game time (dtS, the world's step) on the session. Throws LaunchError, prefixed
    /// "shot N: ", when a shot cannot be fired.
    Tick advance(GameSession& session, double dtS);

    /// The next shot not yet fired, or null.
    const ScriptedShot* pending() const { return m_next < m_shots.size() ? &m_shots[m_next] : nullptr; }
    /// The shot the last advance() fired (1-based number and the shot), if it fired one.
    std::optional<std::size_t> firedNumber() const { return m_firedNow ? std::optional(m_next) : std::nullopt; }
    const ScriptedShot& shot(std::size_t number) const { return m_shots[number - 1]; }
    std::size_t size() const { return m_shots.size(); }
    /// A fired shot's ability is still to come (the window keeps the player's own press out meanwhile).
    bool abilityPending() const { return m_abilityAtS.has_value(); }
    /// The level restarted: the shot in flight is gone, and its ability with it (later shots still fire).
    void dropAbility() { m_abilityAtS.reset(); }

private:
    void fire(GameSession& session);

    std::vector<ScriptedShot> m_shots;
    double m_holdS;
    std::size_t m_next = 0;
    double m_heldS = 0.0;
    std::optional<double> m_abilityAtS; ///< the fired shot's ability time, until it fires
    bool m_firedNow = false;
};

} // namespace abalike
