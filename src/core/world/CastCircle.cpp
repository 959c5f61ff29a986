#include "world/Skin.hpp"
#include "world/WorldBodies.hpp"

#include <box2d/b2_time_of_impact.h>
#include <cmath>

namespace abalike
{

std::optional<double> WorldBodies::castCircle(double radiusM, const FlightState& a, const FlightState& b,
                                              int pieces) const
{
    const b2Vec2 pa(static_cast<float>(a.position.x), static_cast<float>(a.position.y));
    const b2Vec2 pb(static_cast<float>(b.position.x), static_cast<float>(b.position.y));
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

    // The world splits this step into as many Box2D steps as a bird this fast needs (substepsFor), moving the
    // bird an equal share of the chord in each; Box2D starts a contact in two ways, and the preview must see both
    // in every one of them: at the start of a sub-step when the shapes' skins already overlap (b2Contact::Update),
    // or by time of impact inside it (b2World::SolveTOI).
    for (int piece = 0; piece < pieces; ++piece)
    {
        const double s0 = static_cast<double>(piece) / pieces;
        const double s1 = static_cast<double>(piece + 1) / pieces;
        const b2Vec2 from(static_cast<float>(a.position.x + (b.position.x - a.position.x) * s0),
                          static_cast<float>(a.position.y + (b.position.y - a.position.y) * s0));
        const b2Vec2 to(static_cast<float>(a.position.x + (b.position.x - a.position.x) * s1),
                        static_cast<float>(a.position.y + (b.position.y - a.position.y) * s1));
        b2TOIInput input;
        input.proxyA.Set(&circle, 0);
        input.sweepA.localCenter.SetZero();
        input.sweepA.c0 = from;
        input.sweepA.c = to;
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
                b2DistanceInput distanceInput;
                distanceInput.proxyA = input.proxyA;
                distanceInput.proxyB = input.proxyB;
                distanceInput.transformA.Set(from, 0.0f);
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
        if (earliest)
            return (piece + *earliest) / pieces;
    }
    return std::nullopt;
}

} // namespace abalike
