#pragma once

#include <abalike/world/Ability.hpp>
#include <abalike/world/Entity.hpp>
#include <array>
#include <vector>

namespace abalike
{

class WorldBodies;

/// Damage and break-through: the contact impulses of a step become damage; a body that breaks absorbs only its
/// remaining strength and gives the rest back to what struck it (WorldSettings::breakThrough); blasts (the black
/// bird's, TNT crates') push and damage everything within their radius.
class Damage
{
public:
    explicit Damage(WorldBodies& bodies) : m_bodies(bodies) {}

    /// After a step: damage from the recorded contacts, break-through refunds, then the crates that broke explode.
    /// watched: an entity whose refund (the impulse it gave back by breaking) is remembered, -1 for none.
    void applyStep(int watched);
    /// What the watched entity gave back by breaking in the last applyStep (N s; zero when it held).
    const std::array<double, 2>& watchedRefund() const { return m_watchedRefund; }

    /// A radial blast at (x, y): impulse impulseNs (1 - d / R) on every block and pig whose centre is within R, taken
    /// as damage too; appends each push to impulses when given.
    void blast(double x, double y, double radiusM, double impulseNs, std::vector<AbilityImpulse>* impulses, double tS);
    /// The crates that broke since the last call explode, and those their blasts break, in the order they broke.
    void explodeCrates();
    /// TNT blasts since the last call.
    std::vector<BlastEvent> takeBlastEvents();

private:
    /// Break-through: every surviving body that struck a breaking one gets back the rest of the contact impulse
    /// along the contact normal.
    void refundBreakingContacts(const std::vector<double>& keptShare, int watched);
    DefeatCause causeOf(int index) const;
    void damageEntity(int index, double impulseNs, const DefeatCause& cause);

    WorldBodies& m_bodies;
    std::vector<BlastEvent> m_blasts;
    std::vector<int> m_cratesToExplode; ///< TNT crates that broke in this step, blasting after damage
    std::array<double, 2> m_watchedRefund{};
};

} // namespace abalike
