#include "world/Damage.hpp"

#include "world/WorldBodies.hpp"

#include <algorithm>
#include <cmath>

namespace abalike
{

namespace
{
bool damageable(const Entity& e)
{
    return e.alive && (e.kind == EntityKind::Block || e.kind == EntityKind::Pig);
}
} // namespace

void Damage::applyStep(int watched)
{
    const std::vector<Entity>& entities = m_bodies.entities();
    const ContactRecorder& contacts = m_bodies.contacts();
    // Process in index order so results never depend on hash-map iteration order.
    std::vector<std::pair<int, double>> totals(contacts.impulses().begin(), contacts.impulses().end());
    std::sort(totals.begin(), totals.end());
    // A body breaks when the step's impacts reach its remaining strength H; of their total J it absorbs only H,
    // the share H / J of each contact impulse (keptShare; 1 for bodies that hold).
    std::vector<double> keptShare(entities.size(), 1.0);
    bool anyBreaks = false;
    m_watchedRefund = {0.0, 0.0};
    m_watchedHandedOn = {0.0, 0.0};
    for (const auto& [index, impulse] : totals)
    {
        const Entity& e = entities[static_cast<std::size_t>(index)];
        if (damageable(e) && impulse >= e.health && impulse > 0.0)
        {
            keptShare[static_cast<std::size_t>(index)] = e.health / impulse;
            anyBreaks = true;
        }
    }
    std::vector<b2Vec2> givenBack(entities.size(), b2Vec2(0.0f, 0.0f));
    if (anyBreaks && m_bodies.settings().breakThrough)
        refundBreakingContacts(keptShare, watched, givenBack);
    if (anyBreaks && m_bodies.settings().handOnMomentum)
        handOnMomentum(keptShare, givenBack, watched);
    for (const auto& [index, impulse] : totals)
        if (damageable(entities[static_cast<std::size_t>(index)]))
            damageEntity(index, impulse, causeOf(index));
    explodeCrates();
}

namespace
{
/// What a body that broke under hit gives back to its surviving partner (the striker, or what it was pressing on):
/// the part of the contact impulse beyond the broken body's kept share, at most what the partner lost that way since
/// before the contact (a body pinned between the broken one and the ground lost nothing: the ground took the blow).
b2Vec2 refundFor(const ContactRecorder::Hit& hit, bool brokenIsA, double keptShare, bool yields, const b2Body& partner)
{
    // The striker keeps the broken body's share H / J of the contact impulse; a yielding body gives back its rebound
    // too, and friction in the same share (WorldSettings::breakingBodyYields).
    const double kept = yields ? std::min(keptShare, 1.0 / (1.0 + hit.restitution)) : keptShare;
    const double friction = yields ? hit.tangentImpulseNs : 0.0;
    const b2Vec2 pushed =
        static_cast<float>(hit.impulseNs) * hit.normal + static_cast<float>(friction) * b2Cross(hit.normal, 1.0f);
    // b was pushed along the impulse and a against it.
    const float sign = brokenIsA ? -1.0f : 1.0f;
    const b2Vec2 full = (sign * static_cast<float>(1.0 - kept)) * pushed;
    const float length = full.Length();
    if (!(length > 0.0f))
        return {0.0f, 0.0f};
    const b2Vec2 back = (1.0f / length) * full;
    const b2Vec2 before = hit.velocityBefore[brokenIsA ? 1 : 0];
    const float lost = partner.GetMass() * b2Dot(before - partner.GetLinearVelocity(), back);
    return std::clamp(lost, 0.0f, length) * back;
}
} // namespace

void Damage::refundBreakingContacts(const std::vector<double>& keptShare, int watched, std::vector<b2Vec2>& givenBack)
{
    // The solver stopped the striker as if the struck body were unbreakable. A brittle body cannot push back more
    // than its strength: give each surviving partner the rest of the impulse back, at the contact point. In
    // bookkeeping terms the broken body carried that impulse away with it (the first impact's record).
    const bool yields = m_bodies.settings().breakingBodyYields;
    for (const ContactRecorder::Hit& hit : m_bodies.contacts().hits())
    {
        for (const bool brokenIsA : {true, false})
        {
            const int broken = brokenIsA ? hit.a : hit.b;
            const int partner = brokenIsA ? hit.b : hit.a;
            if (broken < 0 || partner < 0 || keptShare[static_cast<std::size_t>(broken)] >= 1.0 ||
                keptShare[static_cast<std::size_t>(partner)] < 1.0)
                continue; // nothing broke, or both did: neither survives to be refunded
            b2Body* body = m_bodies.entity(partner).body;
            if (body == nullptr || body->GetType() != b2_dynamicBody)
                continue;
            const b2Vec2 impulse =
                refundFor(hit, brokenIsA, keptShare[static_cast<std::size_t>(broken)], yields, *body);
            body->ApplyLinearImpulse(impulse, hit.point, true);
            givenBack[static_cast<std::size_t>(broken)] += impulse;
            if (broken == watched)
                m_watchedRefund = {m_watchedRefund.x + impulse.x, m_watchedRefund.y + impulse.y};
        }
    }
}

void Damage::handOnMomentum(const std::vector<double>& keptShare, const std::vector<b2Vec2>& givenBack, int watched)
{
    // A block that breaks leaves as debris, which is only drawn: the momentum it took in this step must not leave
    // the world with it. It goes on to the bodies the block was pushing (its touching contacts whose normal points
    // along its momentum, weighted by their contact impulses), at the contact points, so a tower hit high tips over
    // instead of losing its top block's share of the blow.
    struct Push
    {
        b2Body* body = nullptr;
        b2Vec2 point{0.0f, 0.0f};
        float weight = 0.0f;
    };
    std::vector<Push> pushes;
    for (std::size_t i = 0; i < keptShare.size(); ++i)
    {
        const Entity& broken = m_bodies.entities()[i];
        if (keptShare[i] >= 1.0 || broken.kind != EntityKind::Block || broken.body == nullptr)
            continue;
        b2Body* body = broken.body;
        // What the block took: Box2D's velocity after the step, less what break-through gave back to its strikers.
        const b2Vec2 momentum = body->GetMass() * body->GetLinearVelocity() - givenBack[i];
        if (momentum.LengthSquared() <= 0.0f)
            continue;
        pushes.clear();
        float total = 0.0f;
        for (b2ContactEdge* edge = body->GetContactList(); edge != nullptr; edge = edge->next)
        {
            b2Contact* contact = edge->contact;
            b2Body* other = edge->other;
            const int otherIndex = entityIndexOf(other);
            if (!contact->IsTouching() || !contact->IsEnabled() || other->GetType() != b2_dynamicBody ||
                otherIndex < 0 || keptShare[static_cast<std::size_t>(otherIndex)] < 1.0)
                continue;
            b2WorldManifold manifold;
            contact->GetWorldManifold(&manifold);
            // The manifold's normal points from fixture A to fixture B: turn it to point from the broken block.
            const b2Vec2 normal = contact->GetFixtureA()->GetBody() == body ? manifold.normal : -manifold.normal;
            const int points = contact->GetManifold()->pointCount;
            float impulse = 0.0f;
            b2Vec2 at(0.0f, 0.0f);
            for (int p = 0; p < points; ++p)
            {
                impulse += contact->GetManifold()->points[p].normalImpulse;
                at += (1.0f / static_cast<float>(points)) * manifold.points[p];
            }
            if (b2Dot(momentum, normal) <= 0.0f || !(impulse > 0.0f))
                continue; // not pushed by the block, or not pressed at all
            pushes.push_back({other, at, impulse});
            total += impulse;
        }
        // A block pushes a body at most up to its own speed: a heavy block falling on a light body pinned to the
        // ground would otherwise fling it many times faster than the block moved. What the bodies ahead cannot take
        // stays with the debris.
        const b2Vec2 velocity = (1.0f / body->GetMass()) * momentum;
        const float amount = momentum.Length();
        const b2Vec2 direction = (1.0f / amount) * momentum;
        for (const Push& push : pushes)
        {
            const float share = (push.weight / total) * amount;
            const float room = push.body->GetMass() * b2Dot(velocity - push.body->GetLinearVelocity(), direction);
            const b2Vec2 impulse = std::clamp(room, 0.0f, share) * direction;
            push.body->ApplyLinearImpulse(impulse, push.point, true);
            if (static_cast<int>(i) == watched)
                m_watchedHandedOn = {m_watchedHandedOn.x + impulse.x, m_watchedHandedOn.y + impulse.y};
        }
    }
}

void Damage::releaseSlowBullets()
{
    std::erase_if(m_bullets,
                  [this](int index)
                  {
                      b2Body* body = m_bodies.entity(index).body;
                      if (body == nullptr)
                          return true;
                      if (body->GetLinearVelocity().Length() > kBulletSpeedMps)
                          return false;
                      body->SetBullet(false);
                      return true;
                  });
}

DefeatCause Damage::causeOf(int index) const
{
    // The partner that delivered the most impulse to this body in the step, summed over its sub-steps.
    std::vector<std::pair<int, double>> byPartner;
    for (const ContactRecorder::Hit& hit : m_bodies.contacts().hits())
    {
        if (hit.a != index && hit.b != index)
            continue;
        const int partner = hit.a == index ? hit.b : hit.a;
        const auto it =
            std::find_if(byPartner.begin(), byPartner.end(), [partner](const auto& p) { return p.first == partner; });
        if (it == byPartner.end())
            byPartner.emplace_back(partner, hit.impulseNs);
        else
            it->second += hit.impulseNs;
    }
    int strongest = -1;
    double most = -1.0;
    for (const auto& [partner, impulse] : byPartner)
        if (impulse > most)
        {
            most = impulse;
            strongest = partner;
        }
    if (strongest < 0)
        return {CauseKind::Ground, -1};
    const Entity& e = m_bodies.entity(strongest);
    switch (e.kind)
    {
    case EntityKind::Block:
        return {CauseKind::Block, e.defIndex};
    case EntityKind::Pig:
        return {CauseKind::Pig, e.defIndex};
    case EntityKind::Bird:
        return e.shotBird ? DefeatCause{CauseKind::Bird, -1} : DefeatCause{CauseKind::Ability, -1, e.madeBy};
    case EntityKind::Ground:
    case EntityKind::Terrain:
        break;
    }
    return {CauseKind::Ground, -1};
}

void Damage::damageEntity(int index, double impulseNs, const DefeatCause& cause)
{
    Entity& entity = m_bodies.entity(index);
    if (!damageable(entity))
        return;
    entity.health -= impulseNs;
    if (entity.health > 0.0)
        return;
    if (entity.kind == EntityKind::Block)
        if (const Material* material = m_bodies.catalog().findMaterial(entity.typeName);
            material && material->blastRadiusM > 0)
            m_cratesToExplode.push_back(index);
    m_bodies.destroyEntity(index, true, cause);
}

void Damage::blast(double x, double y, double radiusM, double impulseNs, std::vector<AbilityImpulse>* impulses,
                   double tS)
{
    // Every block and pig whose centre is within R gets a radial impulse J (1 - d / R) and absorbs the same impulse
    // as damage: a block's strength is the impulse it can take, whether it comes through a contact or a blast.
    const b2Vec2 centre(static_cast<float>(x), static_cast<float>(y));
    std::vector<Entity>& entities = m_bodies.entities();
    std::vector<std::pair<int, double>> hits;
    for (std::size_t i = 0; i < entities.size(); ++i)
    {
        Entity& e = entities[i];
        if (!damageable(e) || e.body == nullptr)
            continue;
        const b2Vec2 offset = e.body->GetWorldCenter() - centre;
        const double d = offset.Length();
        if (d >= radiusM)
            continue;
        const double magnitude = impulseNs * (1.0 - d / radiusM);
        const double ux = d > 1e-6 ? offset.x / d : 0.0;
        const double uy = d > 1e-6 ? offset.y / d : 1.0;
        const b2Vec2 impulse(static_cast<float>(magnitude * ux), static_cast<float>(magnitude * uy));
        e.body->ApplyLinearImpulseToCenter(impulse, true);
        // Flung this fast, a block or pig could pass through a thin plank within a step: Box2D sweeps it as a bullet
        // (continuous collision against moving bodies too) until it slows down (releaseSlowBullets).
        if (e.body->GetLinearVelocity().Length() > kBulletSpeedMps && !e.body->IsBullet())
        {
            e.body->SetBullet(true);
            m_bullets.push_back(static_cast<int>(i));
        }
        if (impulses != nullptr)
        {
            const b2Vec2 at = e.body->GetWorldCenter();
            impulses->push_back({tS, at.x, at.y, impulse.x, impulse.y, e.kind == EntityKind::Block ? "block" : "pig"});
        }
        hits.emplace_back(static_cast<int>(i), magnitude);
    }
    for (const auto& [index, magnitude] : hits)
        damageEntity(index, magnitude, {CauseKind::Explosion, -1});
}

void Damage::explodeCrates()
{
    // A crate that broke blasts where it was; a crate its blast breaks joins the queue: chains run in this step, in
    // the order the crates broke.
    for (std::size_t next = 0; next < m_cratesToExplode.size(); ++next)
    {
        const int index = m_cratesToExplode[next];
        const Entity& crate = m_bodies.entity(index);
        const Material* material = m_bodies.catalog().findMaterial(crate.typeName);
        const std::vector<DestroyedEvent>& destroyed = m_bodies.destroyed();
        const auto event = std::find_if(destroyed.rbegin(), destroyed.rend(),
                                        [&](const DestroyedEvent& d)
                                        { return d.kind == EntityKind::Block && d.index == crate.defIndex; });
        if (material == nullptr || event == destroyed.rend())
            continue;
        m_blasts.push_back({m_bodies.time(), event->x, event->y, material->blastRadiusM, crate.defIndex});
        blast(event->x, event->y, material->blastRadiusM, material->blastImpulseNs, nullptr, 0.0);
    }
    m_cratesToExplode.clear();
}

std::vector<BlastEvent> Damage::takeBlastEvents()
{
    std::vector<BlastEvent> events;
    events.swap(m_blasts);
    return events;
}

} // namespace abalike
