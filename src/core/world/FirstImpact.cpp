#include "world/ImpactRecorder.hpp"
#include "world/WorldBodies.hpp"

#include <abalike/world/FirstImpact.hpp>
#include <algorithm>

namespace abalike
{

namespace
{

BodyVelocity velocityOf(const b2Body& body)
{
    return {body.GetLinearVelocity().x, body.GetLinearVelocity().y, body.GetAngularVelocity()};
}

double kinetic(double mass, double inertia, const BodyVelocity& v)
{
    return 0.5 * mass * (v.vx * v.vx + v.vy * v.vy) + 0.5 * inertia * v.omegaRadPerS * v.omegaRadPerS;
}

/// Velocity of the material point p of a body moving with v about its centre c: v + omega x (p - c).
Vec2 pointVelocity(const BodyVelocity& v, const Vec2& centre, const Vec2& p)
{
    return {v.vx - v.omegaRadPerS * (p.y - centre.y), v.vy + v.omegaRadPerS * (p.x - centre.x)};
}

} // namespace

Vec2 FirstImpact::momentumBefore() const
{
    return {birdMassKg * birdBefore.vx + bodyMassKg * bodyBefore.vx,
            birdMassKg * birdBefore.vy + bodyMassKg * bodyBefore.vy};
}

Vec2 FirstImpact::momentumAfter() const
{
    return {birdMassKg * birdAfter.vx + bodyMassKg * bodyAfter.vx,
            birdMassKg * birdAfter.vy + bodyMassKg * bodyAfter.vy};
}

double FirstImpact::kineticBeforeJ() const
{
    return kinetic(birdMassKg, birdInertiaKgM2, birdBefore) + kinetic(bodyMassKg, bodyInertiaKgM2, bodyBefore);
}

double FirstImpact::kineticAfterJ() const
{
    return kinetic(birdMassKg, birdInertiaKgM2, birdAfter) + kinetic(bodyMassKg, bodyInertiaKgM2, bodyAfter);
}

Vec2 FirstImpact::birdChange() const
{
    return {birdMassKg * (birdAfter.vx - birdBefore.vx), birdMassKg * (birdAfter.vy - birdBefore.vy)};
}

Vec2 FirstImpact::exchanged() const
{
    const Vec2 bird = birdChange();
    return {balance.birdOtherContacts.x - bird.x, balance.birdOtherContacts.y - bird.y};
}

Vec2 FirstImpact::bodyChange() const
{
    return {bodyMassKg * (bodyAfter.vx - bodyBefore.vx), bodyMassKg * (bodyAfter.vy - bodyBefore.vy)};
}

Vec2 FirstImpact::balanceResidual() const
{
    const auto bird = birdChange();
    const auto body = bodyChange();
    return bird + body - balance.supports - balance.birdOtherContacts - balance.gravity - balance.breakThrough;
}

std::optional<double> FirstImpact::restitution() const
{
    // Relative velocity of the two contact points along the normal (bird into body): positive while closing.
    const auto closing = [&](const BodyVelocity& bird, const BodyVelocity& body)
    {
        const auto vb = pointVelocity(bird, birdCentre, point);
        const auto vo = pointVelocity(body, bodyCentre, point);
        return (vb.x - vo.x) * normal.x + (vb.y - vo.y) * normal.y;
    };
    const double before = closing(birdBefore, bodyBefore);
    if (!(before > 0.0))
        return std::nullopt;
    return std::max(0.0, -closing(birdAfter, bodyAfter) / before);
}

void ImpactRecorder::finishStep(const Vec2& refund, const Vec2& handedOn, int birdIndex)
{
    if (m_pending < 0 || !m_impact)
        return;
    const Entity& other = m_bodies.entity(m_pending);
    m_pending = -1;
    m_impact->broke = !other.alive;
    Vec2 givenBack{0.0, 0.0};
    if (m_impact->broke)
    {
        // It absorbed only its remaining strength; the impulse given back to the bird is momentum the broken body
        // did not receive (Damage::refundBreakingContacts).
        m_impact->damageNs = std::min(m_impact->damageNs, m_impact->strengthBeforeNs);
        m_impact->bodyAfter.vx -= refund.x / m_impact->bodyMassKg;
        m_impact->bodyAfter.vy -= refund.y / m_impact->bodyMassKg;
        givenBack = refund;
        m_impact->handedOn = handedOn;
    }
    if (birdIndex >= 0)
        m_impact->birdAfter = velocityOf(*m_bodies.entity(birdIndex).body);
    // The break rule's share: what it gave the bird (refund, momentum handed on) less what the body gave back.
    const double m = m_impact->birdMassKg;
    m_impact->balance.breakThrough = {m * (m_impact->birdAfter.vx - m_birdAfterSolver.vx) - givenBack.x,
                                      m * (m_impact->birdAfter.vy - m_birdAfterSolver.vy) - givenBack.y};
}

void ImpactRecorder::snapshot()
{
    // Only while the bird flies free and has touched nothing: then the next contact may be its first impact, and
    // its "before" is the velocity every body has now, before Box2D steps.
    const std::vector<Entity>& entities = m_bodies.entities();
    m_stepStartVelocities.resize(entities.size());
    for (std::size_t i = 0; i < entities.size(); ++i)
        if (const b2Body* body = entities[i].body)
            m_stepStartVelocities[i] = velocityOf(*body);
}

void ImpactRecorder::record(int birdIndex, int otherIndex, double tS)
{
    if (otherIndex < 0 || static_cast<std::size_t>(otherIndex) >= m_stepStartVelocities.size())
        return;
    const Entity& other = m_bodies.entity(otherIndex);
    const Entity& bird = m_bodies.entity(birdIndex);
    if ((other.kind != EntityKind::Block && other.kind != EntityKind::Pig) || other.body == nullptr ||
        bird.body == nullptr)
        return;
    FirstImpact impact;
    impact.tS = tS;
    impact.bodyKind = other.kind;
    impact.bodyIndex = other.defIndex;
    impact.bodyType = other.typeName;
    impact.birdMassKg = bird.body->GetMass();
    impact.birdInertiaKgM2 =
        bird.body->GetInertia() - bird.body->GetMass() * bird.body->GetLocalCenter().LengthSquared();
    impact.bodyMassKg = other.body->GetMass();
    impact.bodyInertiaKgM2 =
        other.body->GetInertia() - other.body->GetMass() * other.body->GetLocalCenter().LengthSquared();
    impact.birdBefore = m_stepStartVelocities[static_cast<std::size_t>(birdIndex)];
    impact.bodyBefore = m_stepStartVelocities[static_cast<std::size_t>(otherIndex)];
    impact.birdAfter = velocityOf(*bird.body);
    impact.bodyAfter = velocityOf(*other.body);
    const ContactRecorder& contacts = m_bodies.contacts();
    const b2Vec2 touch = *contacts.birdTouch();
    impact.birdCentre = {touch.x, touch.y};
    impact.bodyCentre = {other.body->GetWorldCenter().x, other.body->GetWorldCenter().y};
    impact.normal = {contacts.birdTouchNormal().x, contacts.birdTouchNormal().y};
    // The contact point is on the bird's surface along the normal (its designed radius).
    const double radius = 0.5 * bird.widthM;
    impact.point = {touch.x + radius * impact.normal.x, touch.y + radius * impact.normal.y};
    const auto damage = contacts.impulses().find(otherIndex);
    impact.damageNs = damage == contacts.impulses().end() ? 0.0 : damage->second;
    impact.strengthBeforeNs = other.health;
    const ImpulseLedger& ledger = contacts.ledger();
    const ImpulseLedger::Account onBody = ledger.account(otherIndex);
    const ImpulseLedger::Account onBird = ledger.account(birdIndex);
    impact.balance.pushOnBody = onBody.fromBird;
    impact.balance.supports = onBody.contacts - onBody.fromBird;
    // The bird got the opposite of the push it gave; the rest of its contact impulses came from elsewhere.
    impact.balance.birdOtherContacts = onBird.contacts + onBody.fromBird;
    impact.balance.gravity = onBody.gravity + onBird.gravity;
    const std::vector<Entity>& entities = m_bodies.entities();
    for (std::size_t i = 0; i < entities.size(); ++i)
    {
        const int index = static_cast<int>(i);
        const Vec2 pushed = ledger.account(index).fromBird;
        if (index == otherIndex || index == birdIndex || (pushed.x == 0.0 && pushed.y == 0.0))
            continue;
        const Entity& partner = entities[i];
        impact.partners.push_back({partner.kind, partner.defIndex,
                                   partner.kind == EntityKind::Ground    ? std::string("ground")
                                   : partner.kind == EntityKind::Terrain ? std::string("terrain")
                                                                         : partner.typeName,
                                   pushed});
    }
    m_birdAfterSolver = impact.birdAfter;
    m_impact = impact;
    m_pending = otherIndex; // finishStep completes the record once damage is applied
}

} // namespace abalike
