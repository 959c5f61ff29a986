#include "TestCatalog.hpp"

#include <abalike/world/GameWorld.hpp>
#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

/// Catalog whose wood has the given restitution, no friction and cannot break (the test is about momentum).
Catalog isolatedCatalog(double restitution)
{
    return test::catalogWith(
        [restitution](nlohmann::json& root)
        {
            nlohmann::json& wood = test::materialIn(root, "wood");
            wood["restitution"] = restitution;
            wood["friction"] = 0.0;
            wood["strength_ns"] = 1e9;
        });
}

struct Totals
{
    double momentumX = 0.0;
    double momentumY = 0.0;
    double kinetic = 0.0;
};

Totals totals(const GameWorld& world)
{
    Totals t;
    for (const Entity& e : world.entities())
    {
        if (e.kind != EntityKind::Block || e.body == nullptr)
            continue;
        const b2Body& b = *e.body;
        const double m = b.GetMass();
        const double vx = b.GetLinearVelocity().x;
        const double vy = b.GetLinearVelocity().y;
        const double w = b.GetAngularVelocity();
        t.momentumX += m * vx;
        t.momentumY += m * vy;
        t.kinetic += 0.5 * m * (vx * vx + vy * vy) + 0.5 * b.GetInertia() * w * w;
    }
    return t;
}

/// Two bodies in zero gravity meet head on: a light one at +8 m/s and one three times heavier at -3 m/s.
struct HeadOn
{
    Totals before;
    Totals after;
    double relativeSpeedBefore = 0.0;
    double relativeSpeedAfter = 0.0;
    double lightMass = 0.0;
    double heavyMass = 0.0;
};

HeadOn collide(BlockShape shape, double restitution)
{
    const Catalog catalog = isolatedCatalog(restitution);
    LevelDef level;
    level.environment.gravity = 0.0;
    level.blocks.push_back({shape, "wood", 10.0, 5.0, 0.5, 0.5, 0.0});
    level.blocks.push_back({shape, "wood", 12.0, 5.0, 0.866, 0.866, 0.0}); // three times the area
    GameWorld world(level, catalog);
    b2Body* light = world.entities()[1].body;
    b2Body* heavy = world.entities()[2].body;
    light->SetLinearVelocity(b2Vec2(8.0f, 0.0f));
    heavy->SetLinearVelocity(b2Vec2(-3.0f, 0.0f));
    HeadOn result;
    result.lightMass = light->GetMass();
    result.heavyMass = heavy->GetMass();
    result.before = totals(world);
    result.relativeSpeedBefore = light->GetLinearVelocity().x - heavy->GetLinearVelocity().x;
    for (int i = 0; i < 60; ++i)
        world.step();
    result.after = totals(world);
    // The first step rebuilt the bodies (GameWorld::box2d): take them again.
    light = world.entities()[1].body;
    heavy = world.entities()[2].body;
    result.relativeSpeedAfter = heavy->GetLinearVelocity().x - light->GetLinearVelocity().x;
    return result;
}

TEST(Momentum, IsConservedInAHeadOnImpact)
{
    for (const BlockShape shape : {BlockShape::Circle, BlockShape::Box})
        for (const double e : {0.0, 0.2, 0.5, 1.0})
        {
            const HeadOn r = collide(shape, e);
            // Relative to the momentum each body brings (the total is nearly zero by design).
            const double scale = r.lightMass * 8.0 + r.heavyMass * 3.0;
            EXPECT_LT(std::abs(r.after.momentumX - r.before.momentumX), 1e-4 * scale) << "e = " << e;
            EXPECT_LT(std::abs(r.after.momentumY - r.before.momentumY), 1e-4 * scale) << "e = " << e;
            // They did collide: the relative velocity turned round by the restitution.
            EXPECT_NEAR(r.relativeSpeedAfter, e * r.relativeSpeedBefore, 1e-3 * r.relativeSpeedBefore) << "e = " << e;
        }
}

TEST(Momentum, KineticEnergyIsConservedWhenRestitutionIsOne)
{
    for (const BlockShape shape : {BlockShape::Circle, BlockShape::Box})
    {
        const HeadOn r = collide(shape, 1.0);
        EXPECT_NEAR(r.after.kinetic, r.before.kinetic, 1e-4 * r.before.kinetic);
    }
}

TEST(Momentum, KineticEnergyLostMatchesTheRestitution)
{
    // Loss = (1 - e^2) * (reduced mass) * (relative speed)^2 / 2.
    const HeadOn r = collide(BlockShape::Circle, 0.5);
    const double lost = r.before.kinetic - r.after.kinetic;
    const double mu = r.lightMass * r.heavyMass / (r.lightMass + r.heavyMass);
    EXPECT_NEAR(lost, (1.0 - 0.5 * 0.5) * mu * r.relativeSpeedBefore * r.relativeSpeedBefore / 2.0,
                1e-3 * r.before.kinetic);
}

} // namespace
} // namespace abalike
