#pragma once

#include <abalike/world/FirstImpact.hpp>
#include <array>
#include <optional>
#include <vector>

namespace abalike
{

class WorldBodies;

/// Records the launched bird's first impact on a block or a pig: every body's velocity before the step in which it
/// happens, Box2D's velocities after it, and once damage is applied whether the body broke and what it gave back.
class ImpactRecorder
{
public:
    explicit ImpactRecorder(WorldBodies& bodies) : m_bodies(bodies) {}

    /// A new shot: no impact yet.
    void reset() { m_impact.reset(); }
    /// Before a step in which the bird flies free: the velocities its first impact would start from.
    void snapshot();
    /// The bird first touched otherIndex at tS since launch during this step (blocks and pigs only are recorded).
    void record(int birdIndex, int otherIndex, double tS);
    /// The body of an impact recorded in this step until finishStep (-1 when none): damage watches its refund.
    int pendingEntity() const { return m_pending; }
    /// After damage: whether the body broke, what it gave back (refund, N s), the bird's velocity after the step.
    void finishStep(const Vec2& refund, const Vec2& handedOn, int birdIndex);

    const std::optional<FirstImpact>& impact() const { return m_impact; }

private:
    WorldBodies& m_bodies;
    std::vector<BodyVelocity> m_stepStartVelocities; ///< per entity, at the start of a step in free flight
    std::optional<FirstImpact> m_impact;
    int m_pending = -1;
    BodyVelocity m_birdAfterSolver; ///< the pending impact's bird velocity before the break rule acted
};

} // namespace abalike
