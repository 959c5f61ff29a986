#include "world/WorldBodies.hpp"

#include <abalike/level/LevelCatalog.hpp>
#include <algorithm>
#include <cmath>

namespace abalike
{

WorldBodies::WorldBodies(const LevelDef& level, const Catalog& catalog, const WorldSettings& settings)
    : m_level(level), m_catalog(levelCatalog(level, catalog)), m_settings(settings),
      m_contacts(std::make_unique<ContactRecorder>(static_cast<float>(catalog.damageSpeedThresholdMps()),
                                                   static_cast<float>(settings.contactGapM)))
{
}

WorldBodies::~WorldBodies()
{
    // The listener must not see the bodies being destroyed with the world.
    if (m_world)
        m_world->SetContactListener(nullptr);
}

void WorldBodies::build()
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

int WorldBodies::addEntity(Entity entity)
{
    m_entities.push_back(std::move(entity));
    return static_cast<int>(m_entities.size()) - 1;
}

void WorldBodies::destroyEntity(int index, bool scored, const DefeatCause& cause)
{
    Entity& e = entity(index);
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

void WorldBodies::removeBody(int index)
{
    Entity& e = entity(index);
    if (e.body != nullptr)
        m_world->DestroyBody(e.body);
    e.body = nullptr;
    e.alive = false;
}

void WorldBodies::puff(int index)
{
    const Entity& e = entity(index);
    if (e.body == nullptr)
        return;
    DestroyedEvent event;
    event.kind = EntityKind::Bird;
    event.typeName = e.typeName;
    event.x = e.body->GetPosition().x;
    event.y = e.body->GetPosition().y;
    event.timeS = m_time;
    m_destroyed.push_back(event);
}

std::vector<DestroyedEvent> WorldBodies::takeDestroyedEvents()
{
    std::vector<DestroyedEvent> events;
    events.swap(m_destroyed);
    return events;
}

bool WorldBodies::outOfBounds(const Entity& e) const
{
    if (!e.alive || e.body == nullptr || e.body->GetType() != b2_dynamicBody || !e.body->IsAwake())
        return false;
    const auto [left, right, bottom] = m_extent;
    const b2Vec2 p = e.body->GetPosition();
    return !(p.x >= left && p.x <= right && p.y >= bottom);
}

bool WorldBodies::isSettled() const
{
    for (const b2Body* body = m_world->GetBodyList(); body != nullptr; body = body->GetNext())
        if (body->GetType() == b2_dynamicBody && body->IsAwake())
            return false;
    return true;
}

int WorldBodies::pigsAlive() const
{
    return static_cast<int>(std::count_if(m_entities.begin(), m_entities.end(),
                                          [](const Entity& e) { return e.kind == EntityKind::Pig && e.alive; }));
}

bool WorldBodies::hasNonFiniteState() const
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
