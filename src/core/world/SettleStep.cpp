#include "world/SettleStep.hpp"

#include "world/WorldBodies.hpp"
#include "world/WorldStepper.hpp"

#include <abalike/world/SettleCache.hpp>
#include <array>
#include <box2d/box2d.h>
#include <cmath>
#include <map>
#include <unordered_map>

namespace abalike
{

namespace
{

/// Version of what a key covers and a state holds; a change to either makes old keys miss.
constexpr std::uint32_t kSettleFormat = 2;

void addShape(SettleKey& key, const b2Shape& shape)
{
    key.add(static_cast<int>(shape.GetType())).add(shape.m_radius);
    switch (shape.GetType())
    {
    case b2Shape::e_circle:
        key.add(static_cast<const b2CircleShape&>(shape).m_p);
        break;
    case b2Shape::e_polygon:
    {
        const auto& polygon = static_cast<const b2PolygonShape&>(shape);
        key.add(polygon.m_count);
        for (int i = 0; i < polygon.m_count; ++i)
            key.add(polygon.m_vertices[i]);
        break;
    }
    case b2Shape::e_edge:
    {
        const auto& edge = static_cast<const b2EdgeShape&>(shape);
        key.add(edge.m_vertex0).add(edge.m_vertex1).add(edge.m_vertex2).add(edge.m_vertex3).add(edge.m_oneSided);
        break;
    }
    case b2Shape::e_chain:
    {
        const auto& chain = static_cast<const b2ChainShape&>(shape);
        key.add(chain.m_count);
        for (int i = 0; i < chain.m_count; ++i)
            key.add(chain.m_vertices[i]);
        key.add(chain.m_prevVertex).add(chain.m_nextVertex);
        break;
    }
    default:
        break;
    }
}

/// A fixture's place in its body's fixture list: with the body's place, what tells apart the contacts of one pair of
/// bodies with several fixtures (a block on a hollow box's walls, or on a hill's pieces).
std::int32_t fixturePosition(const b2Fixture* fixture)
{
    std::int32_t index = 0;
    for (const b2Fixture* f = fixture->GetBody()->GetFixtureList(); f != nullptr && f != fixture; f = f->GetNext())
        ++index;
    return index;
}

std::unordered_map<const b2Body*, std::int32_t> bodyPositions(b2World& world)
{
    std::unordered_map<const b2Body*, std::int32_t> positions;
    std::int32_t index = 0;
    for (const b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext())
        positions.emplace(body, index++);
    return positions;
}

} // namespace

bool SettleStep::run(bool birdsInPlay)
{
    // A bird launched before the first step flies through the settle step and may touch something in it: that
    // step is solved in place, as before the cache.
    if (!m_bodies.settings().settleCache || m_stepper.settleIterations() <= 0 || birdsInPlay)
        return false;
    const std::uint64_t settleKey = key();
    SettleCache& cache = SettleCache::shared();
    std::shared_ptr<const SettledState> state = cache.find(settleKey);
    m_reused = state && restore(*state);
    if (m_reused)
        m_stepper.markSettleDone();
    else
    {
        m_stepper.stepBox2d(true);
        state = capture();
        cache.store(settleKey, state);
        // The same restore a start from the cache goes through: a new world built from the settled state, so
        // both start alike to the bit, whatever the settle step did to Box2D's broad phase on the way.
        restore(*state);
    }
    m_bodies.contacts().clearStep(); // the settle step deals no damage
    return true;
}

std::uint64_t SettleStep::key() const
{
    const WorldSettings& settings = m_bodies.settings();
    b2World& world = m_bodies.world();
    SettleKey key;
    key.add(kSettleFormat).add(settings.dtS).add(settings.velocityIterations).add(settings.positionIterations);
    key.add(m_stepper.settleIterations()).add(m_stepper.lastSubsteps()).add(settings.contactGapM);
    key.add(settings.cornerChamferM);
    key.add(settings.rollingResistance ? m_bodies.catalog().rollingResistance() : 0.0).add(settings.allowSleep);
    key.add(world.GetGravity());
    for (const Entity& e : m_bodies.entities())
        key.add(static_cast<int>(e.kind))
            .addText(e.typeName)
            .add(static_cast<int>(e.shape))
            .add(e.widthM)
            .add(e.heightM)
            .add(e.wallM)
            .add(e.alive)
            .add(e.body != nullptr);
    for (b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext())
    {
        key.add(static_cast<int>(body->GetType())).add(body->GetPosition()).add(body->GetAngle());
        key.add(body->GetLinearVelocity()).add(body->GetAngularVelocity()).add(body->GetMass()).add(body->GetInertia());
        key.add(body->GetLocalCenter()).add(body->GetLinearDamping()).add(body->GetAngularDamping());
        key.add(body->GetGravityScale()).add(body->IsBullet()).add(body->IsFixedRotation()).add(body->IsAwake());
        key.add(body->IsSleepingAllowed()).add(entityIndexOf(body));
        for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext())
        {
            addShape(key, *fixture->GetShape());
            key.add(fixture->GetDensity()).add(fixture->GetFriction()).add(fixture->GetRestitution());
            key.add(fixture->GetRestitutionThreshold()).add(fixture->IsSensor());
            const b2Filter& filter = fixture->GetFilterData();
            key.add(filter.categoryBits).add(filter.maskBits).add(filter.groupIndex);
        }
    }
    const auto positions = bodyPositions(world);
    for (const b2Contact* contact = world.GetContactList(); contact != nullptr; contact = contact->GetNext())
        key.add(positions.at(contact->GetFixtureA()->GetBody()))
            .add(positions.at(contact->GetFixtureB()->GetBody()))
            .add(fixturePosition(contact->GetFixtureA()))
            .add(fixturePosition(contact->GetFixtureB()))
            .add(contact->GetChildIndexA())
            .add(contact->GetChildIndexB())
            .add(contact->IsTouching());
    return key.value();
}

std::shared_ptr<const SettledState> SettleStep::capture() const
{
    b2World& world = m_bodies.world();
    auto state = std::make_shared<SettledState>();
    for (const b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext())
    {
        const b2Vec2 p = body->GetPosition();
        const b2Vec2 v = body->GetLinearVelocity();
        state->bodies.push_back({p.x, p.y, body->GetAngle(), v.x, v.y, body->GetAngularVelocity()});
    }
    const auto positions = bodyPositions(world);
    for (const b2Contact* contact = world.GetContactList(); contact != nullptr; contact = contact->GetNext())
    {
        SettledState::Contact c{positions.at(contact->GetFixtureA()->GetBody()),
                                positions.at(contact->GetFixtureB()->GetBody()),
                                fixturePosition(contact->GetFixtureA()),
                                fixturePosition(contact->GetFixtureB()),
                                contact->GetChildIndexA(),
                                contact->GetChildIndexB(),
                                *contact->GetManifold()};
        for (int p = c.manifold.pointCount; p < b2_maxManifoldPoints; ++p)
            c.manifold.points[p] = b2ManifoldPoint{}; // Box2D leaves unused points unset
        state->contacts.push_back(c);
    }
    return state;
}

bool SettleStep::restore(const SettledState& state)
{
    if (state.bodies.size() != static_cast<std::size_t>(m_bodies.world().GetBodyCount()))
        return false;
    for (const SettledState::Body& b : state.bodies)
        if (!std::isfinite(b.x) || !std::isfinite(b.y) || !std::isfinite(b.angle) || !std::isfinite(b.vx) ||
            !std::isfinite(b.vy) || !std::isfinite(b.spin))
            return false;
    for (const SettledState::Contact& c : state.contacts)
        if (c.manifold.pointCount < 0 || c.manifold.pointCount > b2_maxManifoldPoints)
            return false;

    m_bodies.build();
    b2World& world = m_bodies.world();
    std::size_t i = 0;
    for (b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext(), ++i)
        if (body->GetType() == b2_dynamicBody)
            body->SetTransform(b2Vec2(state.bodies[i].x, state.bodies[i].y), state.bodies[i].angle);
    // One step without gravity, velocity or iterations finds the contacts at the settled places and moves nothing.
    // It must last a sub-step: Box2D scales the impulses it warm-starts from by the ratio of this step to the last
    // one, which a new world's first step with no time would make zero.
    const b2Vec2 gravity = world.GetGravity();
    world.SetGravity(b2Vec2(0.0f, 0.0f));
    world.Step(static_cast<float>(m_bodies.settings().dtS / m_stepper.lastSubsteps()), 0, 0);
    world.SetGravity(gravity);
    i = 0;
    for (b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext(), ++i)
    {
        if (body->GetType() != b2_dynamicBody)
            continue;
        body->SetLinearVelocity(b2Vec2(state.bodies[i].vx, state.bodies[i].vy));
        body->SetAngularVelocity(state.bodies[i].spin);
        body->SetAwake(true); // also restarts its sleep timer
    }
    // Each contact takes the manifold it had, with the impulses the next step warm-starts from. Two bodies may touch
    // through several fixtures: each of those contacts is its own (keyed by the body pair alone, a hollow box's
    // bottom wall once took the empty manifold of its side wall, lost its warm start and sank a few millimetres).
    std::map<std::array<std::int32_t, 6>, const b2Manifold*> manifolds;
    for (const SettledState::Contact& c : state.contacts)
        manifolds.emplace(std::array<std::int32_t, 6>{c.bodyA, c.bodyB, c.fixtureA, c.fixtureB, c.childA, c.childB},
                          &c.manifold);
    const auto positions = bodyPositions(world);
    for (b2Contact* contact = world.GetContactList(); contact != nullptr; contact = contact->GetNext())
    {
        const auto found = manifolds.find(
            {positions.at(contact->GetFixtureA()->GetBody()), positions.at(contact->GetFixtureB()->GetBody()),
             fixturePosition(contact->GetFixtureA()), fixturePosition(contact->GetFixtureB()),
             contact->GetChildIndexA(), contact->GetChildIndexB()});
        if (found != manifolds.end())
            *contact->GetManifold() = *found->second;
    }
    return true;
}

} // namespace abalike
