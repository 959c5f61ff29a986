#include "world/ContactRecorder.hpp"
#include "world/RollingResistance.hpp"

#include <abalike/level/LevelCatalog.hpp>
#include <abalike/world/GameWorld.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

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

GameWorld::GameWorld(const LevelDef& level, const Catalog& catalog, const WorldSettings& settings)
    : m_level(level), m_catalog(levelCatalog(level, catalog)), m_settings(settings)
{
    if (!(settings.dtS > 0.0) || !std::isfinite(settings.dtS))
        throw std::invalid_argument("world time step must be a finite number > 0");
    if (settings.velocityIterations < 1 || settings.positionIterations < 0 || settings.maxSubsteps < 1 ||
        settings.stackDepthPerSubstep < 1 || settings.maxStackSubsteps < 1)
        throw std::invalid_argument("world iterations and sub-steps must be >= 1");
    if (!(settings.cornerChamferM >= 0.0 && settings.cornerChamferM < 0.02) || !std::isfinite(settings.contactGapM))
        throw std::invalid_argument("corner chamfer must be 0 to 2 cm and the contact gap finite");
    m_contacts = std::make_unique<ContactRecorder>(static_cast<float>(catalog.damageSpeedThresholdMps()),
                                                   static_cast<float>(settings.contactGapM));
    buildWorld();
    measureStackDepth();
    if (settings.settleIterations == WorldSettings::kAutoSettle)
        m_settleIterations =
            std::clamp(kSettlePerDepthSquared * m_stackDepth * m_stackDepth, kMinAutoSettle, kMaxAutoSettle);
    else
        m_settleIterations = std::max(0, settings.settleIterations);
    m_stackSubsteps = stackSubstepsFor(m_stackDepth);
    m_restingStackSubsteps = m_stackSubsteps;
}

void GameWorld::buildWorld()
{
    if (m_world)
        m_world->SetContactListener(nullptr); // the listener must not see the old bodies go
    m_world = std::make_unique<b2World>(b2Vec2(0.0f, static_cast<float>(-m_level.environment.gravity)));
    m_world->SetAllowSleeping(m_settings.allowSleep);
    // Forces (drag on birds) are applied once per step and must act in every sub-step of it.
    m_world->SetAutoClearForces(false);
    m_world->SetContactListener(m_contacts.get());
    m_entities.clear();
    buildLevel();
}

void GameWorld::measureStackDepth()
{
    // A step of zero time finds the contacts and their manifolds without solving or moving anything.
    m_world->Step(0.0f, m_settings.velocityIterations, m_settings.positionIterations);
    m_stackDepth = deepestStack(false, std::numeric_limits<int>::max());
}

int GameWorld::deepestStack(bool restingOnly, int cap) const
{
    // Breadth-first from the static bodies over touching contacts: a body's depth is one more than the shallowest
    // body it touches. With restingOnly, a body that sleeps or moves is not part of a stack: Box2D does not solve
    // a sleeping one, and one that moves is not resting on anything.
    const auto resting = [restingOnly](const b2Body* body)
    {
        if (!restingOnly)
            return true;
        return body->IsAwake() && body->GetLinearVelocity().LengthSquared() <= kRestingSpeedMps * kRestingSpeedMps &&
               std::abs(body->GetAngularVelocity()) <= kRestingSpinRadPerS;
    };
    std::vector<int>& depth = m_stackDepthOf;
    std::vector<int>& frontier = m_stackFrontier;
    std::vector<int>& next = m_stackNext;
    depth.assign(m_entities.size(), -1);
    frontier.clear();
    for (std::size_t i = 0; i < m_entities.size(); ++i)
        if (m_entities[i].body != nullptr && m_entities[i].body->GetType() == b2_staticBody)
        {
            depth[i] = 0;
            frontier.push_back(static_cast<int>(i));
        }
    int deepest = 0;
    while (!frontier.empty() && deepest < cap)
    {
        next.clear();
        for (const int index : frontier)
            for (b2ContactEdge* edge = m_entities[static_cast<std::size_t>(index)].body->GetContactList();
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

int GameWorld::stackSubstepsFor(int depth) const
{
    return std::clamp((depth + m_settings.stackDepthPerSubstep - 1) / m_settings.stackDepthPerSubstep, 1,
                      std::min(m_settings.maxStackSubsteps, m_settings.maxSubsteps));
}

int GameWorld::restingStackSubsteps() const
{
    // Only a stack at rest needs the short sub-step (WorldSettings::stackDepthPerSubstep); once a structure falls,
    // its pieces are no longer resting on each other and a collapse is solved as fast as the level's other bodies.
    if (m_stackSubsteps <= 1)
        return 1;
    return std::min(m_stackSubsteps,
                    stackSubstepsFor(deepestStack(true, m_stackSubsteps * m_settings.stackDepthPerSubstep)));
}

GameWorld::~GameWorld()
{
    // The listener must not see the bodies being destroyed with the world.
    m_world->SetContactListener(nullptr);
}

int GameWorld::addEntity(Entity entity)
{
    m_entities.push_back(std::move(entity));
    return static_cast<int>(m_entities.size()) - 1;
}

double GameWorld::maxSpeedMps() const
{
    return kSubstepTravelShare * b2_maxTranslation * m_settings.maxSubsteps / m_settings.dtS;
}

int GameWorld::substepsFor(double speedMps) const
{
    const double travel = speedMps * m_settings.dtS;
    const double perSubstep = kSubstepTravelShare * b2_maxTranslation;
    return std::clamp(static_cast<int>(std::ceil(travel / perSubstep)), m_restingStackSubsteps, m_settings.maxSubsteps);
}

int GameWorld::substepCount() const
{
    if (m_settings.maxSubsteps <= 1)
        return 1;
    float fastest2 = 0.0f;
    for (const b2Body* body = m_world->GetBodyList(); body != nullptr; body = body->GetNext())
        if (body->GetType() == b2_dynamicBody && body->IsAwake())
            fastest2 = std::max(fastest2, body->GetLinearVelocity().LengthSquared());
    return substepsFor(std::sqrt(static_cast<double>(fastest2)));
}

void GameWorld::step()
{
    m_contacts->clearStep();
    std::array<double, 2> birdStart{};
    if (m_birdIndex >= 0)
    {
        const b2Vec2 p = m_entities[static_cast<std::size_t>(m_birdIndex)].body->GetPosition();
        birdStart = {p.x, p.y};
        driveBirdFlight();
    }
    for (const Projectile& projectile : m_projectiles)
        applyFlightForces(m_entities[static_cast<std::size_t>(projectile.index)].body, *projectile.model,
                          m_time - projectile.shotStartS);

    if (m_birdFlight)
        snapshotImpactVelocities();
    // The settle step solves every stack of the level; later steps only those still at rest.
    m_restingStackSubsteps = m_steps == 0 ? m_stackSubsteps : restingStackSubsteps();
    m_lastSubsteps = substepCount();
    if (m_steps > 0 || !settleThroughCache())
        stepBox2d(m_steps == 0);
    ++m_steps;
    m_world->ClearForces();
    m_time += m_settings.dtS;

    if (m_birdIndex >= 0)
        finishBirdStep(birdStart);
    applyDamage();
    finishImpactStep();
    removeOutOfBounds();
    retireBirds();
    updateCalm();
}

void GameWorld::stepBox2d(bool settle)
{
    const auto h = static_cast<float>(m_settings.dtS / m_lastSubsteps);
    const double rolling = m_settings.rollingResistance ? m_catalog.rollingResistance() : 0.0;
    for (int i = 0; i < m_lastSubsteps; ++i)
    {
        // The first step is the settle step (WorldSettings::settleIterations), in each of its sub-steps.
        m_world->Step(
            h, settle ? std::max(m_settleIterations, m_settings.velocityIterations) : m_settings.velocityIterations,
            m_settings.positionIterations);
        if (rolling > 0.0)
            resistRolling(m_entities, rolling);
        if (settle)
            m_settleSubstepsDone.fetch_add(1, std::memory_order_relaxed);
    }
}

void GameWorld::updateCalm()
{
    for (const Entity& e : m_entities)
    {
        if (!e.alive || e.body == nullptr || e.body->GetType() != b2_dynamicBody || e.kind == EntityKind::Bird ||
            !e.body->IsAwake())
            continue;
        if (e.body->GetLinearVelocity().Length() > kCalmSpeedMps ||
            std::abs(e.body->GetAngularVelocity()) > kCalmSpinRadPerS)
        {
            m_calmSinceS = -1.0;
            return;
        }
    }
    if (m_calmSinceS < 0.0)
        m_calmSinceS = m_time;
}

bool GameWorld::isCalm() const
{
    return m_calmSinceS >= 0.0 && (m_calmSinceS == 0.0 || m_time - m_calmSinceS >= kCalmHoldS - 1e-9);
}

void GameWorld::removeOutOfBounds()
{
    const auto [left, right, bottom] = m_extent;
    for (std::size_t i = 0; i < m_entities.size(); ++i)
    {
        Entity& e = m_entities[i];
        if (!e.alive || e.body == nullptr || e.body->GetType() != b2_dynamicBody || !e.body->IsAwake())
            continue;
        const b2Vec2 p = e.body->GetPosition();
        if (p.x >= left && p.x <= right && p.y >= bottom)
            continue;
        if (static_cast<int>(i) == m_birdIndex)
            removeBird();
        else if (e.kind == EntityKind::Bird)
        {
            for (std::size_t slot = 0; slot < m_projectiles.size(); ++slot)
                if (m_projectiles[slot].index == static_cast<int>(i))
                {
                    removeProjectile(slot);
                    break;
                }
        }
        else
            // A pig off the world is defeated; a block off it is gone but not broken.
            destroyEntity(static_cast<int>(i), e.kind == EntityKind::Pig, {CauseKind::OutOfBounds, -1});
    }
}

void GameWorld::destroyEntity(int index, bool scored, const DefeatCause& cause)
{
    Entity& e = m_entities[static_cast<std::size_t>(index)];
    if (!e.alive)
        return;
    DestroyedEvent event;
    event.kind = e.kind;
    event.typeName = e.typeName;
    event.index = e.defIndex;
    event.timeS = m_time;
    event.cause = cause;
    if (e.body != nullptr)
    {
        event.x = e.body->GetPosition().x;
        event.y = e.body->GetPosition().y;
        m_world->DestroyBody(e.body);
    }
    if (scored)
    {
        if (e.kind == EntityKind::Block)
            event.points = m_catalog.findMaterial(e.typeName)->points;
        else if (e.kind == EntityKind::Pig)
            event.points = m_catalog.findPig(e.typeName)->points;
    }
    e.body = nullptr;
    e.alive = false;
    e.health = 0.0;
    m_destroyed.push_back(event);
}

std::vector<DestroyedEvent> GameWorld::takeDestroyedEvents()
{
    std::vector<DestroyedEvent> events;
    events.swap(m_destroyed);
    return events;
}

bool GameWorld::isSettled() const
{
    for (const b2Body* body = m_world->GetBodyList(); body != nullptr; body = body->GetNext())
        if (body->GetType() == b2_dynamicBody && body->IsAwake())
            return false;
    return true;
}

int GameWorld::pigsAlive() const
{
    return static_cast<int>(std::count_if(m_entities.begin(), m_entities.end(),
                                          [](const Entity& e) { return e.kind == EntityKind::Pig && e.alive; }));
}

bool GameWorld::hasNonFiniteState() const
{
    for (const b2Body* body = m_world->GetBodyList(); body != nullptr; body = body->GetNext())
    {
        const b2Vec2 p = body->GetPosition();
        const b2Vec2 v = body->GetLinearVelocity();
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(v.x) || !std::isfinite(v.y) ||
            !std::isfinite(body->GetAngle()) || !std::isfinite(body->GetAngularVelocity()))
            return true;
    }
    return false;
}

} // namespace abalike
