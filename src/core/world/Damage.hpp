#pragma once

#include <abalike/world/Ability.hpp>
#include <abalike/world/Entity.hpp>
#include <array>
#include <box2d/b2_math.h>
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
    const Vec2& watchedRefund() const { return m_watchedRefund; }
    /// What the watched entity, a block that broke in the last applyStep, handed on to the bodies it was pushing
    /// (N s; zero when it held): the rest of its momentum left with its splinters.
    const Vec2& watchedHandedOn() const { return m_watchedHandedOn; }

    /// A radial blast at (x, y): impulse impulseNs (1 - d / R) on every block and pig whose centre is within R, taken
    /// as damage too; appends each push to impulses when given.
    void blast(double x, double y, double radiusM, double impulseNs, std::vector<AbilityImpulse>* impulses, double tS);
    /// The crates that broke since the last call explode, and those their blasts break, in the order they broke.
    void explodeCrates();
    /// TNT blasts since the last call.
    std::vector<BlastEvent> takeBlastEvents();
    /// After a step: bodies a blast flung are swept as bullets until they are slower than kBulletSpeedMps.
    void releaseSlowBullets();

    /// Faster than this a flung block or pig crosses a 0.2 m plank's width in one 1/60 s step (12 m/s), so a blast
    /// that sends it faster makes it a bullet.
    static constexpr double kBulletSpeedMps = 10.0;

private:
    /// Break-through: every surviving body that struck a breaking one gets back the rest of the contact impulse (the
    /// normal impulse, and with WorldSettings::breakingBodyYields the rebound and friction too).
    /// What each breaking body gave back is added to givenBack (per entity).
    void refundBreakingContacts(const std::vector<double>& keptShare, int watched, std::vector<b2Vec2>& givenBack);
    /// A breaking block's momentum goes on to the bodies it was pushing (WorldSettings::handOnMomentum).
    void handOnMomentum(const std::vector<double>& keptShare, const std::vector<b2Vec2>& givenBack, int watched);
    DefeatCause causeOf(int index) const;
    void damageEntity(int index, double impulseNs, const DefeatCause& cause);

    WorldBodies& m_bodies;
    std::vector<BlastEvent> m_blasts;
    std::vector<int> m_cratesToExplode; ///< TNT crates that broke in this step, blasting after damage
    std::vector<int> m_bullets;         ///< blocks and pigs a blast made bullets, until they slow down
    Vec2 m_watchedRefund{};
    Vec2 m_watchedHandedOn{};
};

} // namespace abalike
