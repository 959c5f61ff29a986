#pragma once

#include <cstdint>
#include <memory>

namespace abalike
{

class WorldBodies;
class WorldStepper;
struct SettledState;

/// The settle step (the world's first) through SettleCache: a world whose bodies and settings match one settled
/// before starts from that state; either way the settled state passes through the same restore, so results do not
/// depend on the cache (WorldSettings::settleCache).
class SettleStep
{
public:
    SettleStep(WorldBodies& bodies, WorldStepper& stepper) : m_bodies(bodies), m_stepper(stepper) {}

    /// Takes the settle step through the cache; false (and nothing done) when this world cannot use it: the cache
    /// is off, there is no settle step, or birds fly through it.
    bool run(bool birdsInPlay);
    /// True when the settle step was taken from the cache rather than solved.
    bool reused() const { return m_reused; }

private:
    std::uint64_t key() const;
    /// The state the settle step left.
    std::shared_ptr<const SettledState> capture() const;
    /// Rebuilds the world and puts it in the settled state: bodies, velocities, contact manifolds; every body
    /// awake. False (and nothing changed) when the state does not fit this world.
    bool restore(const SettledState& state);

    WorldBodies& m_bodies;
    WorldStepper& m_stepper;
    bool m_reused = false;
};

} // namespace abalike
