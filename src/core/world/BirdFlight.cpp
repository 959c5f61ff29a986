#include "world/BirdFlight.hpp"

#include "world/Fixtures.hpp"
#include "world/ImpactRecorder.hpp"
#include "world/Skin.hpp"
#include "world/WorldBodies.hpp"

#include <abalike/level/LevelFlight.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace abalike
{

namespace
{

/// A bird that has touched something leaves the world with a puff once it is slower than kBirdRestSpeedMps for
/// kBirdRestS (it rests or barely rolls), or kBirdGroundS after it first touched the ground or terrain.
constexpr double kBirdRestSpeedMps = 0.5;
constexpr double kBirdRestS = 0.2;
constexpr double kBirdGroundS = 2.0;
/// Longest a bird, a split bird or an egg stays in play after it was launched.
constexpr double kBirdLifetimeS = 12.0;
/// Birds never collide with each other: the three birds of a split start at the same point, an egg inside its
/// bird's outline.
constexpr int16 kBirdGroup = -1;

BodyRef refOf(const Entity& e)
{
    return {e.kind, e.kind == EntityKind::Ground ? -1 : e.defIndex};
}

} // namespace

std::vector<BodyRef> BirdFlight::touchedInStep(b2Body* body) const
{
    // What it touches now, and what it began to touch in the step and left again within it (a glancing hit).
    std::vector<BodyRef> touched;
    const auto add = [&](int index)
    {
        if (index < 0)
            return;
        const BodyRef ref = refOf(m_bodies.entity(index));
        if (std::find(touched.begin(), touched.end(), ref) == touched.end())
            touched.push_back(ref);
    };
    for (const auto& [birdIndex, other] : m_bodies.contacts().birdTouches())
        if (birdIndex == m_birdIndex)
            add(other);
    for (b2ContactEdge* edge = body->GetContactList(); edge != nullptr; edge = edge->next)
        if (edge->contact->IsTouching() && edge->contact->IsEnabled())
            add(entityIndexOf(edge->other));
    return touched;
}

b2Body* BirdFlight::createBody(int index, double radiusM, double massKg, double friction, double restitution,
                               const FlightState& s)
{
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.bullet = true; // continuous collision against everything, so fast birds never pass through
    def.position.Set(static_cast<float>(s.position.x), static_cast<float>(s.position.y));
    def.linearVelocity.Set(static_cast<float>(s.velocity.x), static_cast<float>(s.velocity.y));
    def.angularDamping = 0.8f;
    def.userData = userDataFor(index);
    b2Body* body = m_bodies.world().CreateBody(&def);
    b2FixtureDef fixture;
    const double r = physicsCircleRadius(radiusM);
    fixture.density = static_cast<float>(massKg / (std::numbers::pi * r * r)); // mass exactly the bird's
    fixture.friction = static_cast<float>(friction);
    fixture.restitution = static_cast<float>(restitution);
    fixture.filter.groupIndex = kBirdGroup;
    addCircleFixture(body, radiusM, fixture);
    m_bodies.entity(index).body = body;
    return body;
}

BirdBody BirdFlight::birdBody(const BirdType& bird) const
{
    return birdCollisionBody(bird, m_bodies.lightestBodyKg());
}

void BirdFlight::setEnvironment(const EnvironmentDef& environment)
{
    if (m_birdIndex < 0)
        return;
    const FlightModel model = levelFlightModel(environment, m_birdType);
    IntegratorSettings flightSettings;
    flightSettings.stepper = StepperKind::Rk4;
    flightSettings.dtS = m_bodies.settings().dtS;
    if (m_flight)
    {
        // The flight goes on from where it is under the new forces; its time origin (gusts) stays the launch.
        const double t = m_flight->time();
        const FlightState s = m_flight->state();
        m_flight = std::make_unique<FlightIntegrator>(model, flightSettings);
        m_flight->reset(t, s);
    }
    m_model = std::make_unique<FlightIntegrator>(model, flightSettings);
}

int BirdFlight::launch(const BirdType& bird, const FlightModel& model, const FlightState& s0)
{
    removeAllBirds();
    Entity entity;
    entity.kind = EntityKind::Bird;
    entity.typeName = bird.name;
    entity.shape = BlockShape::Circle;
    entity.widthM = entity.heightM = 2.0 * bird.radiusM;
    m_birdIndex = m_bodies.addEntity(entity);
    m_birdType = bird;
    // Free flight follows the model (true mass and size); Box2D collides the body it can simulate well.
    const BirdBody collision = birdBody(bird);
    b2Body* body = createBody(m_birdIndex, collision.radiusM, collision.massKg, bird.friction, bird.restitution, s0);
    body->SetGravityScale(0.0f); // in free flight the flight model supplies every force

    IntegratorSettings flightSettings;
    flightSettings.stepper = StepperKind::Rk4;
    flightSettings.dtS = m_bodies.settings().dtS;
    m_flight = std::make_unique<FlightIntegrator>(model, flightSettings);
    m_flight->reset(0.0, s0);
    m_model = std::make_unique<FlightIntegrator>(model, flightSettings);
    m_launchTimeS = m_bodies.time();
    m_slowSinceS = -1.0;
    m_groundSinceS = -1.0;
    m_touched = false;
    m_shotContactTimeS.reset();
    m_abilityUsed = false;
    m_contact.reset();
    m_contactKind.reset();
    m_impacts.reset();
    m_path.assign(1, {0.0, s0.position});
    m_pathTouches.assign(1, {});
    m_bodies.contacts().watchBird(body);
    return m_birdIndex;
}

void BirdFlight::removeBird()
{
    if (m_birdIndex < 0)
        return;
    m_bodies.removeBody(m_birdIndex);
    m_birdIndex = -1;
    m_flight.reset();
    m_model.reset();
    m_bodies.contacts().watchBird(nullptr);
}

void BirdFlight::removeProjectile(std::size_t slot)
{
    m_bodies.removeBody(m_projectiles[slot].index);
    m_projectiles.erase(m_projectiles.begin() + static_cast<std::ptrdiff_t>(slot));
}

void BirdFlight::removeProjectileOf(int index)
{
    for (std::size_t slot = 0; slot < m_projectiles.size(); ++slot)
        if (m_projectiles[slot].index == index)
        {
            removeProjectile(slot);
            return;
        }
}

void BirdFlight::removeAllBirds()
{
    removeBird();
    while (!m_projectiles.empty())
        removeProjectile(m_projectiles.size() - 1);
}

FlightState BirdFlight::state() const
{
    if (m_flight)
        return m_flight->state();
    const b2Body* body = m_bodies.entity(m_birdIndex).body;
    const b2Vec2 p = body->GetPosition();
    const b2Vec2 v = body->GetLinearVelocity();
    return {{p.x, p.y}, {v.x, v.y}};
}

void BirdFlight::setVelocity(double vx, double vy)
{
    if (m_flight)
    {
        // Re-seed the flight from the new state: the bird keeps following RK4, from here on along a new path.
        const FlightState s = m_flight->state();
        m_flight->reset(m_flight->time(), {s.position, {vx, vy}});
        return;
    }
    m_bodies.entity(m_birdIndex).body->SetLinearVelocity(b2Vec2(static_cast<float>(vx), static_cast<float>(vy)));
}

void BirdFlight::addProjectile(const ProjectileSpec& spec)
{
    Entity entity;
    entity.kind = EntityKind::Bird;
    entity.typeName = spec.typeName;
    entity.shape = BlockShape::Circle;
    entity.widthM = entity.heightM = 2.0 * spec.radiusM;
    entity.shotBird = spec.shotBird;
    entity.madeBy = m_birdType.ability.get();
    const int index = m_bodies.addEntity(entity);
    createBody(index, spec.radiusM, spec.massKg, m_birdType.friction, m_birdType.restitution, spec.state);
    IntegratorSettings flightSettings;
    flightSettings.dtS = m_bodies.settings().dtS;
    Projectile projectile;
    projectile.index = index;
    projectile.launchTimeS = m_bodies.time();
    projectile.shotStartS = m_launchTimeS;
    projectile.model = std::make_unique<FlightIntegrator>(spec.model, flightSettings);
    m_projectiles.push_back(std::move(projectile));
}

Vec2 BirdFlight::beforeStep()
{
    Vec2 birdStart{};
    if (m_birdIndex >= 0)
    {
        b2Body* body = m_bodies.entity(m_birdIndex).body;
        const b2Vec2 p = body->GetPosition();
        birdStart = {p.x, p.y};
        if (m_flight)
        {
            // Aim Box2D's own position update (x += h v) at the next RK4 state: the bird follows the RK4 path
            // exactly, and its bullet time-of-impact sweeps the same chord the preview casts.
            const FlightStep& step = m_flight->step();
            m_stepStart = step.s0;
            const b2Vec2 target(static_cast<float>(step.s1.position.x), static_cast<float>(step.s1.position.y));
            body->SetLinearVelocity((1.0f / static_cast<float>(m_bodies.settings().dtS)) *
                                    (target - body->GetPosition()));
        }
        else
            applyFlightForces(body, *m_model, m_bodies.time() - m_launchTimeS);
    }
    for (const Projectile& projectile : m_projectiles)
        applyFlightForces(m_bodies.entity(projectile.index).body, *projectile.model,
                          m_bodies.time() - projectile.shotStartS);
    return birdStart;
}

void BirdFlight::applyFlightForces(b2Body* body, const FlightIntegrator& model, double sinceLaunchS)
{
    // Box2D owns the body; the flight model's forces other than gravity (which the world applies) still act on
    // it: drag and wind, from the same right-hand side.
    if (activeTerms(model.model()) == kGravityTerm)
        return;
    const b2Vec2 p = body->GetPosition();
    const b2Vec2 v = body->GetLinearVelocity();
    const FlightState s{{p.x, p.y}, {v.x, v.y}};
    const FlightState dsdt = model.rightHandSide(sinceLaunchS, s);
    const FlightModel& m = model.model();
    double ax = dsdt.velocity.x;
    double ay = dsdt.velocity.y + m.gravity;
    // Drag can at most bring the body to the air's velocity within a step. An explicit force larger than that (a
    // light, wide bird: |lambda| dt > 1) would reverse the relative velocity and grow every step; limiting it is the
    // stiff limit of implicit Euler. Ordinary birds are far from it (|lambda| dt < 0.1) and are not touched.
    const Vec2 gust = m.gusts ? m.gusts->windAt(sinceLaunchS) : Vec2{0.0, 0.0};
    const double relX = s.velocity.x - (m.windX + gust.x);
    const double relY = s.velocity.y - (m.windY + gust.y);
    const double change = std::hypot(ax, ay) * m_bodies.settings().dtS;
    const double relative = std::hypot(relX, relY);
    if (change > relative && change > 0.0)
    {
        ax *= relative / change;
        ay *= relative / change;
    }
    const double mass = body->GetMass();
    body->ApplyForceToCenter(b2Vec2(static_cast<float>(mass * ax), static_cast<float>(mass * ay)), true);
}

void BirdFlight::afterStep(const Vec2& stepStart)
{
    if (m_birdIndex < 0)
        return;
    b2Body* body = m_bodies.entity(m_birdIndex).body;
    const double dtS = m_bodies.settings().dtS;
    const double sinceLaunch = m_bodies.time() - m_launchTimeS;
    const ContactRecorder& contacts = m_bodies.contacts();
    if (!m_contact && contacts.birdTouch())
    {
        // The touch happened on this step's chord (the RK4 chord in free flight, Box2D's move otherwise): its time
        // is the fraction of the chord travelled.
        const b2Vec2 touch = *contacts.birdTouch();
        const double x0 = m_flight ? m_stepStart.position.x : stepStart.x;
        const double y0 = m_flight ? m_stepStart.position.y : stepStart.y;
        const double dx = (m_flight ? m_flight->state().position.x : body->GetPosition().x) - x0;
        const double dy = (m_flight ? m_flight->state().position.y : body->GetPosition().y) - y0;
        const double length2 = dx * dx + dy * dy;
        double fraction = 1.0;
        if (length2 > 0.0)
            fraction = std::clamp(((touch.x - x0) * dx + (touch.y - y0) * dy) / length2, 0.0, 1.0);
        const double t = sinceLaunch - dtS + fraction * dtS;
        m_contact = ContactPoint{t, touch.x, touch.y};
        const int other = contacts.birdTouchOther();
        if (other >= 0)
            m_contactKind = m_bodies.entity(other).kind;
        if (m_flight)
            m_impacts.record(m_birdIndex, other, t);
        m_path.push_back({t, {touch.x, touch.y}});
        m_pathTouches.emplace_back();
        if (other >= 0)
            m_pathTouches.back().push_back(refOf(m_bodies.entity(other)));
        m_flight.reset();
        body->SetGravityScale(1.0f);
    }
    const b2Vec2 p = body->GetPosition();
    m_path.push_back({sinceLaunch, {p.x, p.y}});
    m_pathTouches.push_back(touchedInStep(body));
}

void BirdFlight::updateRest()
{
    const double now = m_bodies.time();
    // What the birds began to touch in this step: the shot's first contact, and when each first met the ground.
    for (const auto& [birdIndex, other] : m_bodies.contacts().birdTouches())
    {
        const bool ground = other >= 0 && (m_bodies.entity(other).kind == EntityKind::Ground ||
                                           m_bodies.entity(other).kind == EntityKind::Terrain);
        if (birdIndex == m_birdIndex)
        {
            m_touched = true;
            if (ground && m_groundSinceS < 0.0)
                m_groundSinceS = now;
            if (!m_shotContactTimeS)
                m_shotContactTimeS = m_contact ? m_launchTimeS + m_contact->t : now;
            continue;
        }
        for (Projectile& projectile : m_projectiles)
            if (projectile.index == birdIndex)
            {
                projectile.touched = true;
                if (ground && projectile.groundSinceS < 0.0)
                    projectile.groundSinceS = now;
                // The split birds are the shot's birds too; an egg is not.
                if (!m_shotContactTimeS && m_bodies.entity(birdIndex).shotBird)
                    m_shotContactTimeS = now;
            }
    }

    const auto slowFor = [now](const b2Body* body, double& slowSinceS, bool mayRest)
    {
        const bool slow = mayRest && body->GetLinearVelocity().Length() < kBirdRestSpeedMps;
        if (!slow)
            slowSinceS = -1.0;
        else if (slowSinceS < 0.0)
            slowSinceS = now;
        return slow ? now - slowSinceS : 0.0;
    };
    const auto done = [now](double rested, double groundSinceS, double launchedS)
    {
        return rested >= kBirdRestS - 1e-9 || (groundSinceS >= 0.0 && now - groundSinceS >= kBirdGroundS - 1e-9) ||
               now - launchedS >= kBirdLifetimeS - 1e-9;
    };
    m_birdDone = false;
    if (m_birdIndex >= 0)
    {
        const b2Body* body = m_bodies.entity(m_birdIndex).body;
        const double rested = slowFor(body, m_slowSinceS, m_touched && !inFreeFlight());
        m_birdDone = done(rested, m_groundSinceS, m_launchTimeS);
    }
    for (Projectile& projectile : m_projectiles)
    {
        const b2Body* body = m_bodies.entity(projectile.index).body;
        const double rested = slowFor(body, projectile.slowSinceS, projectile.touched);
        projectile.done = done(rested, projectile.groundSinceS, projectile.launchTimeS);
    }
}

void BirdFlight::retire()
{
    if (m_birdIndex >= 0 && m_birdDone)
    {
        m_bodies.puff(m_birdIndex);
        removeBird();
    }
    m_birdDone = false;
    for (std::size_t slot = m_projectiles.size(); slot-- > 0;)
        if (m_projectiles[slot].done)
        {
            m_bodies.puff(m_projectiles[slot].index);
            removeProjectile(slot);
        }
}

void BirdFlight::retireAll()
{
    if (m_birdIndex >= 0)
        m_bodies.puff(m_birdIndex);
    for (const Projectile& projectile : m_projectiles)
        m_bodies.puff(projectile.index);
    removeAllBirds();
}

} // namespace abalike
