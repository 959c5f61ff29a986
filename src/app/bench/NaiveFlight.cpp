#include "bench/NaiveFlight.hpp"

#include <abalike/flight/FlightIntegrator.hpp>
#include <abalike/world/Catalog.hpp>

#include <box2d/box2d.h>
#include <numbers>

namespace abalike::app
{

namespace
{

// The same skin compensation as GameWorld (src/core/world/Skin.hpp), so that both worlds touch at the same place.
constexpr float kPolygonInset = b2_polygonRadius - 0.5f * b2_linearSlop;
constexpr float kCircleGrowth = 0.5f * b2_linearSlop;

/// Records where the bird is when its first contact begins. Box2D calls BeginContact with the bodies at the contact
/// pose (for a time-of-impact event, before it moves the bird on for the rest of the step).
class FirstTouch : public b2ContactListener
{
public:
    explicit FirstTouch(const b2Body*& bird) : m_bird(bird) {}

    void BeginContact(b2Contact* contact) override
    {
        const b2Body* a = contact->GetFixtureA()->GetBody();
        const b2Body* b = contact->GetFixtureB()->GetBody();
        if (touch || (a != m_bird && b != m_bird))
            return;
        const b2Vec2 p = m_bird->GetPosition();
        const b2Vec2 v = m_bird->GetLinearVelocity();
        touch = FlightState{{p.x, p.y}, {v.x, v.y}};
    }

    std::optional<FlightState> touch;

private:
    const b2Body*& m_bird;
};

} // namespace

std::optional<FlightState> naiveFirstContact(const ReferenceShot& shot, const NaiveFlightSettings& settings)
{
    const LevelDef level = referenceShotLevel(shot);
    const BirdType& bird = *Catalog::builtin().findBird(shot.bird);
    b2World world(b2Vec2(0.0f, static_cast<float>(-shot.gravity)));
    const b2Body* birdBody = nullptr;
    FirstTouch listener(birdBody);
    world.SetContactListener(&listener);

    b2BodyDef groundDef;
    b2Body* ground = world.CreateBody(&groundDef);
    b2EdgeShape edge;
    const auto groundY = static_cast<float>(level.groundY) - kPolygonInset;
    edge.SetTwoSided(b2Vec2(-300.0f, groundY), b2Vec2(600.0f, groundY));
    ground->CreateFixture(&edge, 0.0f);
    for (const BlockDef& block : level.blocks)
    {
        // The wall is at rest until the bird reaches it, so a static box stands in for the stone block.
        b2PolygonShape box;
        box.SetAsBox(static_cast<float>(block.widthM / 2) - kPolygonInset,
                     static_cast<float>(block.heightM / 2) - kPolygonInset,
                     b2Vec2(static_cast<float>(block.x), static_cast<float>(block.y)), 0.0f);
        ground->CreateFixture(&box, 0.0f);
    }

    FlightModel model;
    model.gravity = shot.gravity;
    model.massKg = bird.massKg;
    model.quadraticDrag = quadraticDragCoefficient(shot.airDensity, bird.dragCoefficient, bird.radiusM);
    model.windX = shot.windX;
    model.windY = shot.windY;
    model.gusts = shot.gusts;
    const FlightIntegrator forces(model, {}); // only its right-hand side is used
    const FlightState s0 = launchState(level.slingshot.x, level.slingshot.y, shot.speedMps, shot.angleDeg);
    const double h = (1.0 / 60.0) / settings.stepsPerFrame;
    FlightState v0 = s0;
    if (settings.halfStepStart)
    {
        const FlightState a0 = forces.rightHandSide(0.0, s0);
        v0.velocity.x -= 0.5 * h * a0.velocity.x;
        v0.velocity.y -= 0.5 * h * a0.velocity.y;
    }

    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.bullet = true;
    def.position.Set(static_cast<float>(s0.position.x), static_cast<float>(s0.position.y));
    def.linearVelocity.Set(static_cast<float>(v0.velocity.x), static_cast<float>(v0.velocity.y));
    b2Body* body = world.CreateBody(&def);
    birdBody = body;
    b2CircleShape circle;
    circle.m_radius = static_cast<float>(bird.radiusM) + kCircleGrowth;
    const double r = circle.m_radius;
    body->CreateFixture(&circle, static_cast<float>(bird.massKg / (std::numbers::pi * r * r)));

    for (int step = 0; step < 20 * 60 * settings.stepsPerFrame; ++step)
    {
        // Drag and wind as a force from the current velocity; gravity is the world's.
        const b2Vec2 p = body->GetPosition();
        const b2Vec2 v = body->GetLinearVelocity();
        const FlightState a = forces.rightHandSide(step * h, {{p.x, p.y}, {v.x, v.y}});
        const double mass = body->GetMass();
        body->ApplyForceToCenter(
            b2Vec2(static_cast<float>(mass * a.velocity.x), static_cast<float>(mass * (a.velocity.y + shot.gravity))),
            true);
        world.Step(static_cast<float>(h), 8, 3);
        if (listener.touch)
            return listener.touch;
    }
    return std::nullopt;
}

} // namespace abalike::app
