#include "world/WorldStepper.hpp"

#include "world/RollingResistance.hpp"
#include "world/WorldBodies.hpp"

#include <abalike/world/GameWorld.hpp>
#include <algorithm>
#include <cmath>
#include <limits>

namespace abalike
{

namespace
{

/// Sub-steps are sized so that the fastest body moves at most this share of b2_maxTranslation in one.
constexpr double kSubstepTravelShare = 0.9;
/// The automatic settle step: kSettlePerDepthSquared x depth^2 velocity iterations, within these bounds. Measured:
/// a 20-block tower needs 2000 to rest to 0.01 mm, a 40-row pyramid 8000 (docs/world-physics.md).
constexpr int kSettlePerDepthSquared = 5;
constexpr int kMinAutoSettle = 2000;
constexpr int kMaxAutoSettle = 10000;

} // namespace

WorldStepper::WorldStepper(WorldBodies& bodies) : m_bodies(bodies)
{
    const WorldSettings& settings = bodies.settings();
    // A step of zero time finds the contacts and their manifolds without solving or moving anything.
    bodies.world().Step(0.0f, settings.velocityIterations, settings.positionIterations);
    m_stackDepth = deepestStack(false, std::numeric_limits<int>::max());
    if (settings.settleIterations == WorldSettings::kAutoSettle)
        m_settleIterations =
            std::clamp(kSettlePerDepthSquared * m_stackDepth * m_stackDepth, kMinAutoSettle, kMaxAutoSettle);
    else
        m_settleIterations = std::max(0, settings.settleIterations);
    m_stackSubsteps = stackSubstepsFor(m_stackDepth);
    m_restingStackSubsteps = m_stackSubsteps;
}

int WorldStepper::deepestStack(bool restingOnly, int cap) const
{
    // Breadth-first from the static bodies over touching contacts: a body's depth is one more than the shallowest
    // body it touches. With restingOnly, a body that sleeps or moves is not part of a stack: Box2D does not solve
    // a sleeping one, and one that moves is not resting on anything.
    const auto resting = [restingOnly](const b2Body* body)
    {
        if (!restingOnly)
            return true;
        return body->IsAwake() &&
               body->GetLinearVelocity().LengthSquared() <= GameWorld::kRestingSpeedMps * GameWorld::kRestingSpeedMps &&
               std::abs(body->GetAngularVelocity()) <= GameWorld::kRestingSpinRadPerS;
    };
    const std::vector<Entity>& entities = m_bodies.entities();
    std::vector<int>& depth = m_stackDepthOf;
    std::vector<int>& frontier = m_stackFrontier;
    std::vector<int>& next = m_stackNext;
    depth.assign(entities.size(), -1);
    frontier.clear();
    for (std::size_t i = 0; i < entities.size(); ++i)
        if (entities[i].body != nullptr && entities[i].body->GetType() == b2_staticBody)
        {
            depth[i] = 0;
            frontier.push_back(static_cast<int>(i));
        }
    int deepest = 0;
    while (!frontier.empty() && deepest < cap)
    {
        next.clear();
        for (const int index : frontier)
            for (b2ContactEdge* edge = entities[static_cast<std::size_t>(index)].body->GetContactList();
                 edge != nullptr; edge = edge->next)
            {
                const int other = entityIndexOf(edge->other);
                if (!edge->contact->IsTouching() || other < 0 || depth[static_cast<std::size_t>(other)] >= 0 ||
                    edge->other->GetType() != b2_dynamicBody || !resting(edge->other))
                    continue;
                depth[static_cast<std::size_t>(other)] = depth[static_cast<std::size_t>(index)] + 1;
                deepest = std::max(deepest, depth[static_cast<std::size_t>(other)]);
                next.push_back(other);
            }
        frontier.swap(next);
    }
    return deepest;
}

int WorldStepper::stackSubstepsFor(int depth) const
{
    const WorldSettings& settings = m_bodies.settings();
    return std::clamp((depth + settings.stackDepthPerSubstep - 1) / settings.stackDepthPerSubstep, 1,
                      std::min(settings.maxStackSubsteps, settings.maxSubsteps));
}

int WorldStepper::restingStackSubsteps() const
{
    // Only a stack at rest needs the short sub-step (WorldSettings::stackDepthPerSubstep); once a structure falls,
    // its pieces are no longer resting on each other and a collapse is solved as fast as the level's other bodies.
    if (m_stackSubsteps <= 1)
        return 1;
    return std::min(m_stackSubsteps,
                    stackSubstepsFor(deepestStack(true, m_stackSubsteps * m_bodies.settings().stackDepthPerSubstep)));
}

double WorldStepper::maxSpeedMps() const
{
    const WorldSettings& settings = m_bodies.settings();
    return kSubstepTravelShare * b2_maxTranslation * settings.maxSubsteps / settings.dtS;
}

int WorldStepper::substepsFor(double speedMps) const
{
    const WorldSettings& settings = m_bodies.settings();
    const double travel = speedMps * settings.dtS;
    const double perSubstep = kSubstepTravelShare * b2_maxTranslation;
    return std::clamp(static_cast<int>(std::ceil(travel / perSubstep)), m_restingStackSubsteps, settings.maxSubsteps);
}

int WorldStepper::substepCount() const
{
    if (m_bodies.settings().maxSubsteps <= 1)
        return 1;
    float fastest2 = 0.0f;
    for (const b2Body* body = m_bodies.world().GetBodyList(); body != nullptr; body = body->GetNext())
        if (body->GetType() == b2_dynamicBody && body->IsAwake())
            fastest2 = std::max(fastest2, body->GetLinearVelocity().LengthSquared());
    return substepsFor(std::sqrt(static_cast<double>(fastest2)));
}

void WorldStepper::planStep(bool settle)
{
    // The settle step solves every stack of the level; later steps only those still at rest.
    m_restingStackSubsteps = settle ? m_stackSubsteps : restingStackSubsteps();
    m_lastSubsteps = substepCount();
}

void WorldStepper::stepBox2d(bool settle)
{
    const WorldSettings& settings = m_bodies.settings();
    const auto h = static_cast<float>(settings.dtS / m_lastSubsteps);
    const double rolling = settings.rollingResistance ? m_bodies.catalog().rollingResistance() : 0.0;
    ImpulseLedger& ledger = m_bodies.contacts().ledger();
    for (int i = 0; i < m_lastSubsteps; ++i)
    {
        ledger.beginSubstep(m_bodies.entities());
        // The first step is the settle step (WorldSettings::settleIterations), in each of its sub-steps.
        m_bodies.world().Step(
            h, settle ? std::max(m_settleIterations, settings.velocityIterations) : settings.velocityIterations,
            settings.positionIterations);
        ledger.endSubstep(m_bodies.entities(), m_bodies.world().GetGravity(), h);
        if (rolling > 0.0)
            resistRolling(m_bodies.entities(), rolling);
        if (settle)
            m_settleSubstepsDone.fetch_add(1, std::memory_order_relaxed);
    }
}

void WorldStepper::updateCalm()
{
    for (const Entity& e : m_bodies.entities())
    {
        if (!e.alive || e.body == nullptr || e.body->GetType() != b2_dynamicBody || e.kind == EntityKind::Bird ||
            !e.body->IsAwake())
            continue;
        if (e.body->GetLinearVelocity().Length() > GameWorld::kCalmSpeedMps ||
            std::abs(e.body->GetAngularVelocity()) > GameWorld::kCalmSpinRadPerS)
        {
            m_calmSinceS = -1.0;
            return;
        }
    }
    if (m_calmSinceS < 0.0)
        m_calmSinceS = m_bodies.time();
}

bool WorldStepper::isCalm() const
{
    return m_calmSinceS >= 0.0 &&
           (m_calmSinceS == 0.0 || m_bodies.time() - m_calmSinceS >= GameWorld::kCalmHoldS - 1e-9);
}

} // namespace abalike
