#include "world/ContactRecorder.hpp"

#include <algorithm>

namespace abalike
{

void ContactRecorder::BeginContact(b2Contact* contact)
{
    b2Body* a = contact->GetFixtureA()->GetBody();
    b2Body* b = contact->GetFixtureB()->GetBody();
    if (a->IsBullet())
        m_birdTouches.emplace_back(entityIndexOf(a), entityIndexOf(b));
    if (b->IsBullet())
        m_birdTouches.emplace_back(entityIndexOf(b), entityIndexOf(a));
    if (m_bird == nullptr || m_birdTouch)
        return;
    // During a time-of-impact sub-step Box2D has already moved the bird to the moment of impact.
    if (a == m_bird || b == m_bird)
    {
        m_birdTouch = m_bird->GetPosition();
        m_birdTouchOther = entityIndexOf(a == m_bird ? b : a);
        // The manifold's normal points from fixture A to fixture B.
        b2WorldManifold manifold;
        contact->GetWorldManifold(&manifold);
        m_birdTouchNormal = a == m_bird ? manifold.normal : -manifold.normal;
    }
}

void ContactRecorder::PreSolve(b2Contact* contact, const b2Manifold* /*oldManifold*/)
{
    m_ledger.preSolve(contact);
    // Closing speed along the normal before the solver acts: what tells an impact from resting contact.
    b2WorldManifold manifold;
    contact->GetWorldManifold(&manifold);
    const b2Body* a = contact->GetFixtureA()->GetBody();
    const b2Body* b = contact->GetFixtureB()->GetBody();
    const int points = contact->GetManifold()->pointCount;
    if (m_contactGap >= 0.0f && !a->IsBullet() && !b->IsBullet())
    {
        // Box2D treats shapes as touching as soon as their skins overlap; resting surfaces sit b2_linearSlop into
        // them (Skin.hpp). Closer than that plus the gap, the designed surfaces touch; further, they do not, and the
        // contact would only prop one body on the rounded corner of the other. Birds keep Box2D's own rule, which
        // the preview mirrors.
        float deepest = manifold.separations[0];
        for (int i = 1; i < points; ++i)
            deepest = std::min(deepest, manifold.separations[i]);
        if (deepest > m_contactGap - b2_linearSlop)
        {
            contact->SetEnabled(false);
            return;
        }
    }
    float closing = 0.0f;
    for (int i = 0; i < points; ++i)
    {
        const b2Vec2 va = a->GetLinearVelocityFromWorldPoint(manifold.points[i]);
        const b2Vec2 vb = b->GetLinearVelocityFromWorldPoint(manifold.points[i]);
        closing = std::max(closing, -b2Dot(vb - va, manifold.normal));
    }
    // Resting contacts (nearly all of them) are not stored: PostSolve ignores what it does not find.
    if (closing >= m_threshold)
        m_approaches[contact] = {closing, {a->GetLinearVelocity(), b->GetLinearVelocity()}};
    else if (!m_approaches.empty())
        m_approaches.erase(contact);
}

void ContactRecorder::PostSolve(b2Contact* contact, const b2ContactImpulse* impulse)
{
    m_ledger.postSolve(contact, impulse, m_bird);
    const auto it = m_approaches.find(contact);
    if (it == m_approaches.end() || it->second.closing < m_threshold)
        return; // resting contact never hurts
    double total = 0.0;
    for (int i = 0; i < impulse->count; ++i)
        total += impulse->normalImpulses[i];
    if (!(total > 0.0))
        return;
    Hit hit;
    hit.a = entityIndexOf(contact->GetFixtureA()->GetBody());
    hit.b = entityIndexOf(contact->GetFixtureB()->GetBody());
    hit.impulseNs = total;
    for (int i = 0; i < impulse->count; ++i)
        hit.tangentImpulseNs += impulse->tangentImpulses[i];
    hit.restitution = it->second.closing > contact->GetRestitutionThreshold() ? contact->GetRestitution() : 0.0;
    hit.velocityBefore = it->second.velocity;
    b2WorldManifold manifold;
    contact->GetWorldManifold(&manifold);
    hit.normal = manifold.normal;
    const int points = std::max(1, contact->GetManifold()->pointCount);
    for (int i = 0; i < points; ++i)
        hit.point += (1.0f / static_cast<float>(points)) * manifold.points[i];
    for (const int index : {hit.a, hit.b})
        if (index >= 0)
            m_impulses[index] += total;
    m_hits.push_back(hit);
}

} // namespace abalike
