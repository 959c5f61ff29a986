#include "world/RollingResistance.hpp"

#include <box2d/box2d.h>
#include <cmath>

namespace abalike
{

void resistRolling(const std::vector<Entity>& entities, double coefficient)
{
    for (const Entity& e : entities)
    {
        if (e.body == nullptr || !e.body->IsAwake() || e.shape != BlockShape::Circle ||
            (e.kind != EntityKind::Pig && e.kind != EntityKind::Block))
            continue;
        const double spin = e.body->GetAngularVelocity();
        if (spin == 0.0)
            continue;
        // The normal impulses Box2D just applied to the body (N s over the step), summed over its contacts.
        double normalImpulse = 0.0;
        for (const b2ContactEdge* edge = e.body->GetContactList(); edge != nullptr; edge = edge->next)
        {
            const b2Contact* contact = edge->contact;
            if (!contact->IsTouching() || !contact->IsEnabled())
                continue;
            const b2Manifold* manifold = contact->GetManifold();
            for (int i = 0; i < manifold->pointCount; ++i)
                normalImpulse += manifold->points[i].normalImpulse;
        }
        // Angular impulse coefficient x J x r against the spin, never reversing it.
        const double brake = coefficient * normalImpulse * (e.widthM / 2) / e.body->GetInertia();
        e.body->SetAngularVelocity(
            static_cast<float>(std::abs(spin) <= brake ? 0.0 : spin - std::copysign(brake, spin)));
    }
}

} // namespace abalike
