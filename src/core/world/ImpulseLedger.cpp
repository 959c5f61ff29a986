#include "world/ImpulseLedger.hpp"

#include "world/ContactRecorder.hpp"

namespace abalike
{

namespace
{

/// Only contacts with a bullet or a static (or kinematic) body take part in Box2D's time-of-impact solves.
bool mayBeSolvedAtImpact(const b2Contact* contact)
{
    const b2Body* a = contact->GetFixtureA()->GetBody();
    const b2Body* b = contact->GetFixtureB()->GetBody();
    return a->IsBullet() || b->IsBullet() || a->GetType() != b2_dynamicBody || b->GetType() != b2_dynamicBody;
}

} // namespace

void ImpulseLedger::startStep(bool active)
{
    m_active = active;
    m_accounts.clear();
}

void ImpulseLedger::beginSubstep(const std::vector<Entity>& entities)
{
    if (!m_active)
        return;
    m_normals.clear();
    m_startTransforms.assign(entities.size(), b2Transform());
    m_awakeAtStart.assign(entities.size(), 0);
    m_solvedInIsland.assign(entities.size(), 0);
    for (std::size_t i = 0; i < entities.size(); ++i)
        if (const b2Body* body = entities[i].body)
        {
            m_startTransforms[i] = body->GetTransform();
            m_awakeAtStart[i] = body->IsAwake() ? 1 : 0;
        }
}

void ImpulseLedger::endSubstep(const std::vector<Entity>& entities, const b2Vec2& gravity, float h)
{
    if (!m_active)
        return;
    // Box2D integrates the bodies of its islands: those awake when the sub-step began and those it woke into one
    // through a contact. A body woken only by a time-of-impact solve is moved, not integrated, in that sub-step.
    for (std::size_t i = 0; i < entities.size() && i < m_awakeAtStart.size(); ++i)
    {
        const b2Body* body = entities[i].body;
        if (body == nullptr || body->GetType() != b2_dynamicBody || !(m_awakeAtStart[i] || m_solvedInIsland[i]))
            continue;
        const double weight = static_cast<double>(h) * body->GetGravityScale() * body->GetMass();
        Account& account = accountOf(static_cast<int>(i));
        account.gravity.x += weight * gravity.x;
        account.gravity.y += weight * gravity.y;
    }
}

void ImpulseLedger::preSolve(b2Contact* contact)
{
    if (!m_active || !mayBeSolvedAtImpact(contact))
        return;
    b2WorldManifold manifold;
    contact->GetWorldManifold(&manifold);
    m_normals[contact] = manifold.normal;
}

b2Vec2 ImpulseLedger::normalOf(b2Contact* contact) const
{
    if (const auto stored = m_normals.find(contact); stored != m_normals.end())
        return stored->second;
    // Solved in the regular solve, which starts from the sub-step's first positions (the contact was not updated
    // in this sub-step, or was updated there without moving anything).
    const b2Fixture* a = contact->GetFixtureA();
    const b2Fixture* b = contact->GetFixtureB();
    const auto startOf = [this](const b2Body* body)
    {
        const int index = entityIndexOf(const_cast<b2Body*>(body));
        return index >= 0 && static_cast<std::size_t>(index) < m_startTransforms.size()
                   ? m_startTransforms[static_cast<std::size_t>(index)]
                   : body->GetTransform();
    };
    b2WorldManifold manifold;
    manifold.Initialize(contact->GetManifold(), startOf(a->GetBody()), a->GetShape()->m_radius, startOf(b->GetBody()),
                        b->GetShape()->m_radius);
    return manifold.normal;
}

void ImpulseLedger::postSolve(b2Contact* contact, const b2ContactImpulse* impulse, const b2Body* bird)
{
    if (!m_active)
        return;
    const b2Vec2 normal = normalOf(contact);
    const b2Vec2 tangent(normal.y, -normal.x); // b2Cross(normal, 1), as Box2D's contact solver
    double px = 0.0;
    double py = 0.0;
    for (int i = 0; i < impulse->count; ++i)
    {
        px += static_cast<double>(impulse->normalImpulses[i]) * normal.x +
              static_cast<double>(impulse->tangentImpulses[i]) * tangent.x;
        py += static_cast<double>(impulse->normalImpulses[i]) * normal.y +
              static_cast<double>(impulse->tangentImpulses[i]) * tangent.y;
    }
    b2Body* bodyA = contact->GetFixtureA()->GetBody();
    b2Body* bodyB = contact->GetFixtureB()->GetBody();
    const int a = entityIndexOf(bodyA);
    const int b = entityIndexOf(bodyB);
    // A contact with no PreSolve in this sub-step, or between two dynamic bodies that are not bullets, can only
    // have been solved by the regular solve: both its bodies were in an island.
    const bool regular = !mayBeSolvedAtImpact(contact) || !m_normals.contains(contact);
    // The solver pushes B along the normal and A against it.
    for (const auto& [index, sign, other] : {std::tuple{a, -1.0, bodyB}, std::tuple{b, 1.0, bodyA}})
    {
        if (index < 0)
            continue;
        Account& account = accountOf(index);
        account.contacts.x += sign * px;
        account.contacts.y += sign * py;
        if (other == bird)
        {
            account.fromBird.x += sign * px;
            account.fromBird.y += sign * py;
        }
        if (regular && static_cast<std::size_t>(index) < m_solvedInIsland.size())
            m_solvedInIsland[static_cast<std::size_t>(index)] = 1;
    }
}

ImpulseLedger::Account ImpulseLedger::account(int index) const
{
    return index >= 0 && static_cast<std::size_t>(index) < m_accounts.size()
               ? m_accounts[static_cast<std::size_t>(index)]
               : Account{};
}

ImpulseLedger::Account& ImpulseLedger::accountOf(int index)
{
    if (static_cast<std::size_t>(index) >= m_accounts.size())
        m_accounts.resize(static_cast<std::size_t>(index) + 1);
    return m_accounts[static_cast<std::size_t>(index)];
}

} // namespace abalike
