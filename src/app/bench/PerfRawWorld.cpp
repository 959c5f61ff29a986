#include "bench/PerfParts.hpp"

#include <algorithm>
#include <box2d/box2d.h>

namespace abalike::app
{

std::unique_ptr<b2World> cloneWorld(const b2World& from, bool allowSleep)
{
    auto world = std::make_unique<b2World>(from.GetGravity());
    world->SetAllowSleeping(allowSleep);
    std::vector<const b2Body*> bodies;
    for (const b2Body* b = from.GetBodyList(); b != nullptr; b = b->GetNext())
        bodies.push_back(b);
    std::reverse(bodies.begin(), bodies.end());
    for (const b2Body* b : bodies)
    {
        b2BodyDef def;
        def.type = b->GetType();
        def.position = b->GetPosition();
        def.angle = b->GetAngle();
        def.linearVelocity = b->GetLinearVelocity();
        def.angularVelocity = b->GetAngularVelocity();
        def.linearDamping = b->GetLinearDamping();
        def.angularDamping = b->GetAngularDamping();
        def.allowSleep = b->IsSleepingAllowed();
        def.awake = b->IsAwake();
        def.fixedRotation = b->IsFixedRotation();
        def.bullet = b->IsBullet();
        def.gravityScale = b->GetGravityScale();
        b2Body* body = world->CreateBody(&def);
        std::vector<const b2Fixture*> fixtures;
        for (const b2Fixture* f = b->GetFixtureList(); f != nullptr; f = f->GetNext())
            fixtures.push_back(f);
        std::reverse(fixtures.begin(), fixtures.end());
        for (const b2Fixture* f : fixtures)
        {
            b2FixtureDef fd;
            fd.shape = f->GetShape();
            fd.friction = f->GetFriction();
            fd.restitution = f->GetRestitution();
            fd.restitutionThreshold = f->GetRestitutionThreshold();
            fd.density = f->GetDensity();
            fd.isSensor = f->IsSensor();
            fd.filter = f->GetFilterData();
            body->CreateFixture(&fd);
        }
    }
    return world;
}

void stepRawLike(b2World& world, const GameWorld& like, bool settle)
{
    const WorldSettings& settings = like.settings();
    const int substeps = like.stackSubsteps();
    const auto h = static_cast<float>(settings.dtS / substeps);
    const int velocityIterations =
        settle ? std::max(like.settleIterations(), settings.velocityIterations) : settings.velocityIterations;
    for (int i = 0; i < substeps; ++i)
        world.Step(h, velocityIterations, settings.positionIterations);
}

} // namespace abalike::app
