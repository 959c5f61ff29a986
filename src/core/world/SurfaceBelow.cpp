#include "world/WorldBodies.hpp"

#include <algorithm>
#include <box2d/box2d.h>

namespace abalike
{

namespace
{
/// Keeps the nearest hit on a static body (terrain, the ground); blocks, pigs and birds move and are not a floor.
class StaticHit : public b2RayCastCallback
{
public:
    float ReportFixture(b2Fixture* fixture, const b2Vec2& point, const b2Vec2& normal, float fraction) override
    {
        (void)normal;
        if (fixture->GetBody()->GetType() != b2_staticBody || fixture->IsSensor())
            return -1.0f; // ignore it and go on
        m_hitY = point.y;
        return fraction; // clip the ray here: only nearer hits are reported after this
    }
    std::optional<float> m_hitY;
};
} // namespace

double WorldBodies::surfaceBelow(double x, double fromY) const
{
    const double groundY = m_level.groundY;
    if (!(fromY > groundY))
        return groundY;
    StaticHit hit;
    m_world->RayCast(&hit, b2Vec2(static_cast<float>(x), static_cast<float>(fromY)),
                     b2Vec2(static_cast<float>(x), static_cast<float>(groundY - 0.01)));
    return hit.m_hitY ? std::max(groundY, static_cast<double>(*hit.m_hitY)) : groundY;
}

} // namespace abalike
