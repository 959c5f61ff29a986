#include "world/ContactRecorder.hpp"
#include "world/Skin.hpp"

#include <abalike/world/GameWorld.hpp>
#include <box2d/b2_time_of_impact.h>

namespace abalike
{

std::optional<double> GameWorld::castCircle(double radiusM, const FlightState& a, const FlightState& b) const
{
    const b2Vec2 pa(static_cast<float>(a[0]), static_cast<float>(a[1]));
    const b2Vec2 pb(static_cast<float>(b[0]), static_cast<float>(b[1]));
    b2CircleShape circle;
    circle.m_radius = physicsCircleRadius(radiusM);

    b2AABB box;
    const float margin = circle.m_radius + b2_polygonRadius + b2_linearSlop;
    box.lowerBound = b2Min(pa, pb) - b2Vec2(margin, margin);
    box.upperBound = b2Max(pa, pb) + b2Vec2(margin, margin);

    struct Query : b2QueryCallback
    {
        std::vector<b2Fixture*> fixtures;
        const std::vector<Entity>* entities = nullptr;
        bool ReportFixture(b2Fixture* fixture) override
        {
            // Birds in the world (a split, an egg) are not level geometry.
            const int index = entityIndexOf(fixture->GetBody());
            const bool bird = index >= 0 && (*entities)[static_cast<std::size_t>(index)].kind == EntityKind::Bird;
            if (!bird && !fixture->IsSensor())
                fixtures.push_back(fixture);
            return true;
        }
    } query;
    query.entities = &m_entities;
    m_world->QueryAABB(&query, box);

    // The same time-of-impact computation b2World::SolveTOI runs for a bullet against a resting body.
    b2TOIInput input;
    input.proxyA.Set(&circle, 0);
    input.sweepA.localCenter.SetZero();
    input.sweepA.c0 = pa;
    input.sweepA.c = pb;
    input.sweepA.a0 = input.sweepA.a = 0.0f;
    input.sweepA.alpha0 = 0.0f;
    input.tMax = 1.0f;

    std::optional<double> earliest;
    for (b2Fixture* fixture : query.fixtures)
    {
        const b2Body* body = fixture->GetBody();
        input.sweepB.localCenter = body->GetLocalCenter();
        input.sweepB.c0 = input.sweepB.c = body->GetWorldCenter();
        input.sweepB.a0 = input.sweepB.a = body->GetAngle();
        input.sweepB.alpha0 = 0.0f;
        const b2Shape* shape = fixture->GetShape();
        for (int child = 0; child < shape->GetChildCount(); ++child)
        {
            if (!b2TestOverlap(fixture->GetAABB(child), box))
                continue;
            input.proxyB.Set(shape, child);
            // Box2D starts a contact in two ways, and the preview must see both: at the start of a step when
            // the shapes' skins already overlap (b2Contact::Update), or by time of impact inside the step.
            b2DistanceInput distanceInput;
            distanceInput.proxyA = input.proxyA;
            distanceInput.proxyB = input.proxyB;
            distanceInput.transformA.Set(pa, 0.0f);
            distanceInput.transformB = body->GetTransform();
            distanceInput.useRadii = false;
            b2SimplexCache cache;
            cache.count = 0;
            b2DistanceOutput distance;
            b2Distance(&distance, &cache, &distanceInput);
            if (distance.distance < input.proxyA.m_radius + input.proxyB.m_radius)
            {
                earliest = 0.0;
                continue;
            }
            b2TOIOutput output;
            b2TimeOfImpact(&output, &input);
            if (output.state == b2TOIOutput::e_touching && (!earliest || output.t < *earliest))
                earliest = output.t;
        }
    }
    return earliest;
}

} // namespace abalike
