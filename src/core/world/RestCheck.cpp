#include "world/ContactRecorder.hpp"

#include <abalike/util/Angles.hpp>
#include <abalike/world/RestCheck.hpp>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

namespace abalike
{

namespace
{

/// A contact whose normal is steeper than 30 degrees from the horizontal holds one body up on the other.
constexpr float kSupportNormalY = 0.5f;

/// Where a body was designed to be: centre and angle.
struct Pose
{
    double x = 0.0;
    double y = 0.0;
    double angle = 0.0;
};

Pose designedPose(const LevelDef& level, const Entity& e)
{
    if (e.kind == EntityKind::Block)
    {
        const BlockDef& b = level.blocks[static_cast<std::size_t>(e.defIndex)];
        return {b.x, b.y, b.angleDeg * kDegToRad};
    }
    const PigDef& p = level.pigs[static_cast<std::size_t>(e.defIndex)];
    return {p.x, p.y, 0.0};
}

/// Largest distance any corner of the entity's bounding box moved from its designed pose (the centre for
/// circles, whose turning is not a move).
double displacement(const Entity& e, const Pose& designed)
{
    const b2Vec2 p = e.body->GetPosition();
    const double dx = p.x - designed.x;
    const double dy = p.y - designed.y;
    if (e.shape == BlockShape::Circle)
        return std::hypot(dx, dy);
    const double a1 = e.body->GetAngle();
    double worst = 0.0;
    for (const double sx : {-0.5, 0.5})
        for (const double sy : {-0.5, 0.5})
        {
            const double cx = sx * e.widthM;
            const double cy = sy * e.heightM;
            const double mx =
                dx + (std::cos(a1) - std::cos(designed.angle)) * cx - (std::sin(a1) - std::sin(designed.angle)) * cy;
            const double my =
                dy + (std::sin(a1) - std::sin(designed.angle)) * cx + (std::cos(a1) - std::cos(designed.angle)) * cy;
            worst = std::max(worst, std::hypot(mx, my));
        }
    return worst;
}

std::string describe(const Entity& e)
{
    std::ostringstream out;
    out << (e.kind == EntityKind::Pig    ? "pig "
            : e.kind == EntityKind::Bird ? "bird "
                                         : "block ")
        << e.defIndex << " (" << e.typeName << ")";
    return out.str();
}

} // namespace

MassRatio worstStackMassRatio(const GameWorld& world)
{
    MassRatio worst;
    // GetContactList() of a const world gives const contacts, whose bodies' GetUserData() is non-const in 2.4.
    b2World& box2d = const_cast<b2World&>(world.box2d());
    for (b2Contact* c = box2d.GetContactList(); c != nullptr; c = c->GetNext())
    {
        if (!c->IsTouching())
            continue;
        b2Body* a = c->GetFixtureA()->GetBody();
        b2Body* b = c->GetFixtureB()->GetBody();
        if (a->GetType() != b2_dynamicBody || b->GetType() != b2_dynamicBody)
            continue;
        // The manifold normal points from A to B: mostly up means B rests on A.
        b2WorldManifold manifold;
        c->GetWorldManifold(&manifold);
        if (std::abs(manifold.normal.y) < kSupportNormalY)
            continue; // side by side, not one on the other
        b2Body* upper = manifold.normal.y > 0.0f ? b : a;
        b2Body* lower = upper == a ? b : a;
        const double ratio = static_cast<double>(upper->GetMass()) / static_cast<double>(lower->GetMass());
        if (ratio <= worst.ratio)
            continue;
        worst.ratio = ratio;
        worst.heavier = describe(world.entities()[static_cast<std::size_t>(entityIndexOf(upper))]);
        worst.lighter = describe(world.entities()[static_cast<std::size_t>(entityIndexOf(lower))]);
    }
    return worst;
}

RestReport checkRest(const LevelDef& level, const Catalog& catalog, double seconds, const WorldSettings& settings,
                     double toleranceM)
{
    GameWorld world(level, catalog, settings);
    RestReport report;
    report.seconds = seconds;
    report.toleranceM = toleranceM;
    report.stackDepth = world.stackDepth();
    report.stackSubsteps = world.stackSubsteps();

    std::vector<int> tracked; // entity index of each reported body
    std::vector<Pose> designed;
    for (std::size_t i = 0; i < world.entities().size(); ++i)
    {
        const Entity& e = world.entities()[i];
        if (e.kind != EntityKind::Block && e.kind != EntityKind::Pig)
            continue;
        tracked.push_back(static_cast<int>(i));
        designed.push_back(designedPose(level, e));
        report.bodies.push_back({e.kind, e.defIndex, e.typeName, 0.0, 0.0, false, false, std::nullopt});
    }

    const int steps = static_cast<int>(std::lround(seconds / world.dt()));
    for (int step = 0; step < steps; ++step)
    {
        world.step();
        if (step == 0)
            report.worstMassRatio = worstStackMassRatio(world);
        for (std::size_t k = 0; k < tracked.size(); ++k)
        {
            const Entity& e = world.entities()[static_cast<std::size_t>(tracked[k])];
            if (e.body == nullptr)
                continue;
            BodyRest& body = report.bodies[k];
            body.finalDisplacementM = displacement(e, designed[k]);
            body.maxDisplacementM = std::max(body.maxDisplacementM, body.finalDisplacementM);
            if (!body.startedS && (body.finalDisplacementM > BodyRest::kStartedMovingM || e.health < e.maxHealth))
                body.startedS = static_cast<double>(step + 1) * world.dt();
        }
    }
    // Contacts of bodies at rest: the pairs the solver has to hold up.
    const MassRatio atEnd = worstStackMassRatio(world);
    if (atEnd.ratio > report.worstMassRatio.ratio)
        report.worstMassRatio = atEnd;

    for (std::size_t k = 0; k < tracked.size(); ++k)
    {
        const Entity& e = world.entities()[static_cast<std::size_t>(tracked[k])];
        BodyRest& body = report.bodies[k];
        body.destroyed = !e.alive;
        body.damaged = e.health < e.maxHealth;
        report.destroyedBodies += body.destroyed ? 1 : 0;
        report.damagedBodies += body.damaged ? 1 : 0;
        report.maxFinalDisplacementM = std::max(report.maxFinalDisplacementM, body.finalDisplacementM);
        if (report.worstBody < 0 || body.maxDisplacementM > report.maxDisplacementM)
        {
            report.worstBody = static_cast<int>(k);
            report.maxDisplacementM = body.maxDisplacementM;
        }
    }
    report.settled = world.isSettled();
    return report;
}

std::string RestReport::summary() const
{
    std::ostringstream out;
    out << std::fixed << std::setprecision(1) << (passed() ? "stands" : "does not stand") << " after " << seconds
        << " s: max move " << std::setprecision(3) << maxDisplacementM * 1000.0 << " mm";
    if (worstBody >= 0)
    {
        const BodyRest& b = bodies[static_cast<std::size_t>(worstBody)];
        out << " (" << (b.kind == EntityKind::Pig ? "pig " : "block ") << b.defIndex << ", " << b.typeName << ")";
    }
    out << std::setprecision(1) << " of " << toleranceM * 1000.0 << " mm allowed, ";
    if (damagedBodies == 0 && destroyedBodies == 0)
        out << "no damage";
    else
        out << damagedBodies << " damaged, " << destroyedBodies << " destroyed";
    out << std::setprecision(2) << ", worst mass ratio " << worstMassRatio.ratio;
    if (!worstMassRatio.heavier.empty())
        out << " (" << worstMassRatio.heavier << " on " << worstMassRatio.lighter << ")";
    out << (settled ? ", asleep" : ", still awake");
    if (!passed() && maxDisplacementM > toleranceM && stackDepth >= kDeepStack)
        out << "; the deepest stack is " << stackDepth << " bodies, solved in " << stackSubsteps
            << " sub-steps per step: Box2D holds a stack that deep only approximately, and an off-centre load or a"
               " heavy body high on a narrow column makes it lean; centre the load, widen the column or make it"
               " shorter (docs/world-physics.md, \"What the world cannot hold\")";
    return out.str();
}

} // namespace abalike
