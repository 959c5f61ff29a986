#pragma once

#include "world/ImpulseLedger.hpp"

#include <array>
#include <box2d/box2d.h>
#include <optional>
#include <unordered_map>
#include <vector>

namespace abalike
{

/// Entity index stored in a body's user data (0 means "not an entity").
inline int entityIndexOf(b2Body* body)
{
    return static_cast<int>(body->GetUserData().pointer) - 1; // GetUserData() is non-const in Box2D 2.4
}

/// Records what happens during a Box2D step; the world's parts act on it after the step, because bodies cannot be
/// destroyed inside callbacks (Box2D 2.4's rule).
class ContactRecorder final : public b2ContactListener
{
public:
    /// contactGap: see WorldSettings::contactGapM (negative: every touching contact acts, as in plain Box2D).
    ContactRecorder(float damageSpeedThreshold, float contactGap)
        : m_threshold(damageSpeedThreshold), m_contactGap(contactGap)
    {
    }

    /// The bird whose first touch should be recorded (null for none).
    void watchBird(const b2Body* bird)
    {
        m_bird = bird;
        m_birdTouch.reset();
        m_birdTouchOther = -1;
    }
    /// Where the watched bird was when it first touched something.
    const std::optional<b2Vec2>& birdTouch() const { return m_birdTouch; }
    /// Entity index of what the watched bird first touched (-1 if none or not an entity).
    int birdTouchOther() const { return m_birdTouchOther; }
    /// Unit normal of that first contact, pointing from the bird into what it touched.
    const b2Vec2& birdTouchNormal() const { return m_birdTouchNormal; }

    /// One impact of the last step between two entities: a contact closing faster than the damage threshold, in
    /// one Box2D sub-step. The normal points from a into b: b was pushed along it, a against it.
    struct Hit
    {
        int a = -1; ///< entity index (-1: not an entity)
        int b = -1;
        double impulseNs = 0.0;
        /// The restitution Box2D applied to the contact (0 when it closed slower than the restitution threshold):
        /// impulseNs / (1 + restitution) of the impulse stopped the approach, the rest was the rebound.
        double restitution = 0.0;
        /// Friction impulse along Box2D's tangent, b2Cross(normal, 1): b was pushed along it too, a against it.
        double tangentImpulseNs = 0.0;
        b2Vec2 normal{0.0f, 0.0f};
        b2Vec2 point{0.0f, 0.0f};
        /// The bodies' linear velocities before the solver acted on the contact (a's, b's).
        std::array<b2Vec2, 2> velocityBefore{};
    };

    /// Touches that began during the last step between a bird (any bullet body: the launched bird, split birds,
    /// eggs) and an entity: (bird index, other index).
    const std::vector<std::pair<int, int>>& birdTouches() const { return m_birdTouches; }

    /// Impact impulses (N s) per entity index during the last step.
    const std::unordered_map<int, double>& impulses() const { return m_impulses; }
    /// Every impact of the last step, in the order Box2D solved them (deterministic).
    const std::vector<Hit>& hits() const { return m_hits; }
    void clearStep()
    {
        m_impulses.clear();
        m_approaches.clear();
        m_hits.clear();
        m_birdTouches.clear();
    }

    /// The step's impulses as vectors, kept while the watched bird flies free (its first impact's balance).
    ImpulseLedger& ledger() { return m_ledger; }
    const ImpulseLedger& ledger() const { return m_ledger; }

    void BeginContact(b2Contact* contact) override;
    void PreSolve(b2Contact* contact, const b2Manifold* oldManifold) override;
    void PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) override;

private:
    float m_threshold;
    float m_contactGap;
    const b2Body* m_bird = nullptr;
    std::optional<b2Vec2> m_birdTouch;
    int m_birdTouchOther = -1;
    b2Vec2 m_birdTouchNormal{0.0f, 0.0f};
    /// An impact about to be solved: how fast it closes and the bodies' velocities before the solver.
    struct Approach
    {
        float closing = 0.0f;
        std::array<b2Vec2, 2> velocity{};
    };
    std::unordered_map<const b2Contact*, Approach> m_approaches; ///< only contacts closing above the threshold
    std::unordered_map<int, double> m_impulses;
    std::vector<Hit> m_hits;
    std::vector<std::pair<int, int>> m_birdTouches;
    ImpulseLedger m_ledger;
};

} // namespace abalike
