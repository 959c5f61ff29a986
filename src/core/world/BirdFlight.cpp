#include "world/ContactRecorder.hpp"
#include "world/Fixtures.hpp"
#include "world/Skin.hpp"

#include <abalike/level/LevelFlight.hpp>
#include <abalike/world/GameWorld.hpp>
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

} // namespace

b2Body* GameWorld::createBirdBody(int index, double radiusM, double massKg, double friction, double restitution,
                                  const FlightState& s)
{
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.bullet = true; // continuous collision against everything, so fast birds never pass through
    def.position.Set(static_cast<float>(s[0]), static_cast<float>(s[1]));
    def.linearVelocity.Set(static_cast<float>(s[2]), static_cast<float>(s[3]));
    def.angularDamping = 0.8f;
    def.userData = userDataFor(index);
    b2Body* body = m_world->CreateBody(&def);
    b2FixtureDef fixture;
    const double r = physicsCircleRadius(radiusM);
    fixture.density = static_cast<float>(massKg / (std::numbers::pi * r * r)); // mass exactly the bird's
    fixture.friction = static_cast<float>(friction);
    fixture.restitution = static_cast<float>(restitution);
    fixture.filter.groupIndex = kBirdGroup;
    addCircleFixture(body, radiusM, fixture);
    m_entities[static_cast<std::size_t>(index)].body = body;
    return body;
}

BirdBody GameWorld::birdBody(const BirdType& bird) const
{
    return birdCollisionBody(bird, m_lightestBodyKg);
}

void GameWorld::setEnvironment(const EnvironmentDef& environment)
{
    m_level.environment = environment;
    m_world->SetGravity(b2Vec2(0.0f, static_cast<float>(-environment.gravity)));
    if (m_birdIndex < 0)
        return;
    const FlightModel model = levelFlightModel(environment, m_birdType);
    IntegratorSettings flightSettings;
    flightSettings.stepper = StepperKind::Rk4;
    flightSettings.dtS = m_settings.dtS;
    if (m_birdFlight)
    {
        // The flight goes on from where it is under the new forces; its time origin (gusts) stays the launch.
        const double t = m_birdFlight->time();
        const FlightState s = m_birdFlight->state();
        m_birdFlight = std::make_unique<FlightIntegrator>(model, flightSettings);
        m_birdFlight->reset(t, s);
    }
    m_birdModel = std::make_unique<FlightIntegrator>(model, flightSettings);
}

int GameWorld::launchBird(const BirdType& bird, const FlightModel& model, const FlightState& s0)
{
    removeAllBirds();
    Entity entity;
    entity.kind = EntityKind::Bird;
    entity.typeName = bird.name;
    entity.shape = BlockShape::Circle;
    entity.widthM = entity.heightM = 2.0 * bird.radiusM;
    m_birdIndex = addEntity(entity);
    m_birdType = bird;
    // Free flight follows the model (true mass and size); Box2D collides the body it can simulate well.
    const BirdBody collision = birdBody(bird);
    b2Body* body =
        createBirdBody(m_birdIndex, collision.radiusM, collision.massKg, bird.friction, bird.restitution, s0);
    body->SetGravityScale(0.0f); // in free flight the flight model supplies every force

    IntegratorSettings flightSettings;
    flightSettings.stepper = StepperKind::Rk4;
    flightSettings.dtS = m_settings.dtS;
    m_birdFlight = std::make_unique<FlightIntegrator>(model, flightSettings);
    m_birdFlight->reset(0.0, s0);
    m_birdModel = std::make_unique<FlightIntegrator>(model, flightSettings);
    m_birdLaunchTime = m_time;
    m_birdSlowSinceS = -1.0;
    m_birdGroundSinceS = -1.0;
    m_birdTouched = false;
    m_shotContactTimeS.reset();
    m_abilityUsed = false;
    m_birdContact.reset();
    m_birdContactKind.reset();
    m_birdImpact.reset();
    m_birdPath.assign(1, {0.0, s0[0], s0[1]});
    m_contacts->watchBird(body);
    return m_birdIndex;
}

void GameWorld::removeBird()
{
    if (m_birdIndex < 0)
        return;
    Entity& bird = m_entities[static_cast<std::size_t>(m_birdIndex)];
    if (bird.body != nullptr)
        m_world->DestroyBody(bird.body);
    bird.body = nullptr;
    bird.alive = false;
    m_birdIndex = -1;
    m_birdFlight.reset();
    m_birdModel.reset();
    m_contacts->watchBird(nullptr);
}

void GameWorld::removeProjectile(std::size_t slot)
{
    Entity& entity = m_entities[static_cast<std::size_t>(m_projectiles[slot].index)];
    if (entity.body != nullptr)
        m_world->DestroyBody(entity.body);
    entity.body = nullptr;
    entity.alive = false;
    m_projectiles.erase(m_projectiles.begin() + static_cast<std::ptrdiff_t>(slot));
}

void GameWorld::removeAllBirds()
{
    removeBird();
    while (!m_projectiles.empty())
        removeProjectile(m_projectiles.size() - 1);
}

const Entity* GameWorld::bird() const
{
    return m_birdIndex >= 0 ? &m_entities[static_cast<std::size_t>(m_birdIndex)] : nullptr;
}

FlightState GameWorld::birdState() const
{
    if (m_birdFlight)
        return m_birdFlight->state();
    const b2Body* body = m_entities[static_cast<std::size_t>(m_birdIndex)].body;
    const b2Vec2 p = body->GetPosition();
    const b2Vec2 v = body->GetLinearVelocity();
    return {p.x, p.y, v.x, v.y};
}

void GameWorld::setBirdVelocity(double vx, double vy)
{
    if (m_birdFlight)
    {
        // Re-seed the flight from the new state: the bird keeps following RK4, from here on along a new path.
        const FlightState s = m_birdFlight->state();
        m_birdFlight->reset(m_birdFlight->time(), {s[0], s[1], vx, vy});
        return;
    }
    m_entities[static_cast<std::size_t>(m_birdIndex)].body->SetLinearVelocity(
        b2Vec2(static_cast<float>(vx), static_cast<float>(vy)));
}

int GameWorld::addProjectile(const std::string& typeName, double radiusM, double massKg, const FlightState& s,
                             const FlightModel& model)
{
    Entity entity;
    entity.kind = EntityKind::Bird;
    entity.typeName = typeName;
    entity.shape = BlockShape::Circle;
    entity.widthM = entity.heightM = 2.0 * radiusM;
    const int index = addEntity(entity);
    createBirdBody(index, radiusM, massKg, m_birdType.friction, m_birdType.restitution, s);
    IntegratorSettings flightSettings;
    flightSettings.dtS = m_settings.dtS;
    Projectile projectile;
    projectile.index = index;
    projectile.launchTimeS = m_time;
    projectile.shotStartS = m_birdLaunchTime;
    projectile.model = std::make_unique<FlightIntegrator>(model, flightSettings);
    m_projectiles.push_back(std::move(projectile));
    return index;
}

void GameWorld::driveBirdFlight()
{
    b2Body* body = m_entities[static_cast<std::size_t>(m_birdIndex)].body;
    if (m_birdFlight)
    {
        // Aim Box2D's own position update (x += h v) at the next RK4 state: the bird follows the RK4 path
        // exactly, and its bullet time-of-impact sweeps the same chord the preview casts.
        const FlightStep& step = m_birdFlight->step();
        m_birdStepStart = step.s0;
        const b2Vec2 target(static_cast<float>(step.s1[0]), static_cast<float>(step.s1[1]));
        body->SetLinearVelocity((1.0f / static_cast<float>(m_settings.dtS)) * (target - body->GetPosition()));
        return;
    }
    applyFlightForces(body, *m_birdModel, m_time - m_birdLaunchTime);
}

void GameWorld::applyFlightForces(b2Body* body, const FlightIntegrator& model, double sinceLaunchS)
{
    // Box2D owns the body; the flight model's forces other than gravity (which the world applies) still act on
    // it: drag and wind, from the same right-hand side.
    if (activeTerms(model.model()) == kGravityTerm)
        return;
    const b2Vec2 p = body->GetPosition();
    const b2Vec2 v = body->GetLinearVelocity();
    const FlightState s{p.x, p.y, v.x, v.y};
    const FlightState dsdt = model.rightHandSide(sinceLaunchS, s);
    const FlightModel& m = model.model();
    double ax = dsdt[2];
    double ay = dsdt[3] + m.gravity;
    // Drag can at most bring the body to the air's velocity within a step. An explicit force larger than that (a
    // light, wide bird: |lambda| dt > 1) would reverse the relative velocity and grow every step; limiting it is the
    // stiff limit of implicit Euler. Ordinary birds are far from it (|lambda| dt < 0.1) and are not touched.
    const std::array<double, 2> gust = m.gusts ? m.gusts->windAt(sinceLaunchS) : std::array<double, 2>{0.0, 0.0};
    const double relX = s[2] - (m.windX + gust[0]);
    const double relY = s[3] - (m.windY + gust[1]);
    const double change = std::hypot(ax, ay) * m_settings.dtS;
    const double relative = std::hypot(relX, relY);
    if (change > relative && change > 0.0)
    {
        ax *= relative / change;
        ay *= relative / change;
    }
    const double mass = body->GetMass();
    body->ApplyForceToCenter(b2Vec2(static_cast<float>(mass * ax), static_cast<float>(mass * ay)), true);
}

void GameWorld::finishBirdStep(const std::array<double, 2>& stepStart)
{
    b2Body* body = m_entities[static_cast<std::size_t>(m_birdIndex)].body;
    const double sinceLaunch = m_time - m_birdLaunchTime;
    if (!m_birdContact && m_contacts->birdTouch())
    {
        // The touch happened on this step's chord (the RK4 chord in free flight, Box2D's move otherwise): its time
        // is the fraction of the chord travelled.
        const b2Vec2 touch = *m_contacts->birdTouch();
        const double x0 = m_birdFlight ? m_birdStepStart[0] : stepStart[0];
        const double y0 = m_birdFlight ? m_birdStepStart[1] : stepStart[1];
        const double dx = (m_birdFlight ? m_birdFlight->state()[0] : body->GetPosition().x) - x0;
        const double dy = (m_birdFlight ? m_birdFlight->state()[1] : body->GetPosition().y) - y0;
        const double length2 = dx * dx + dy * dy;
        double fraction = 1.0;
        if (length2 > 0.0)
            fraction = std::clamp(((touch.x - x0) * dx + (touch.y - y0) * dy) / length2, 0.0, 1.0);
        const double t = sinceLaunch - m_settings.dtS + fraction * m_settings.dtS;
        m_birdContact = ContactPoint{t, touch.x, touch.y};
        const int other = m_contacts->birdTouchOther();
        if (other >= 0)
            m_birdContactKind = m_entities[static_cast<std::size_t>(other)].kind;
        if (m_birdFlight)
            recordFirstImpact(other, t);
        m_birdPath.push_back({t, touch.x, touch.y});
        m_birdFlight.reset();
        body->SetGravityScale(1.0f);
    }
    const b2Vec2 p = body->GetPosition();
    m_birdPath.push_back({sinceLaunch, p.x, p.y});
}

void GameWorld::retireBirds()
{
    // What the birds began to touch in this step: the shot's first contact, and when each first met the ground.
    for (const auto& [birdIndex, other] : m_contacts->birdTouches())
    {
        const bool ground = other >= 0 && (m_entities[static_cast<std::size_t>(other)].kind == EntityKind::Ground ||
                                           m_entities[static_cast<std::size_t>(other)].kind == EntityKind::Terrain);
        if (birdIndex == m_birdIndex)
        {
            m_birdTouched = true;
            if (ground && m_birdGroundSinceS < 0.0)
                m_birdGroundSinceS = m_time;
            if (!m_shotContactTimeS)
                m_shotContactTimeS = m_birdContact ? m_birdLaunchTime + m_birdContact->t : m_time;
            continue;
        }
        for (Projectile& projectile : m_projectiles)
            if (projectile.index == birdIndex)
            {
                projectile.touched = true;
                if (ground && projectile.groundSinceS < 0.0)
                    projectile.groundSinceS = m_time;
                // The split birds are the shot's birds too; an egg is not.
                if (!m_shotContactTimeS && m_entities[static_cast<std::size_t>(birdIndex)].typeName != "egg")
                    m_shotContactTimeS = m_time;
            }
    }

    const auto slowFor = [this](const b2Body* body, double& slowSinceS, bool mayRest)
    {
        const bool slow = mayRest && body->GetLinearVelocity().Length() < kBirdRestSpeedMps;
        if (!slow)
            slowSinceS = -1.0;
        else if (slowSinceS < 0.0)
            slowSinceS = m_time;
        return slow ? m_time - slowSinceS : 0.0;
    };
    const auto done = [this](double rested, double groundSinceS, double launchedS)
    {
        return rested >= kBirdRestS - 1e-9 || (groundSinceS >= 0.0 && m_time - groundSinceS >= kBirdGroundS - 1e-9) ||
               m_time - launchedS >= kBirdLifetimeS - 1e-9;
    };
    if (m_birdIndex >= 0)
    {
        const b2Body* body = m_entities[static_cast<std::size_t>(m_birdIndex)].body;
        const double rested = slowFor(body, m_birdSlowSinceS, m_birdTouched && !birdInFreeFlight());
        if (done(rested, m_birdGroundSinceS, m_birdLaunchTime))
        {
            puff(m_birdIndex);
            removeBird();
        }
    }
    for (std::size_t slot = m_projectiles.size(); slot-- > 0;)
    {
        Projectile& projectile = m_projectiles[slot];
        const b2Body* body = m_entities[static_cast<std::size_t>(projectile.index)].body;
        const double rested = slowFor(body, projectile.slowSinceS, projectile.touched);
        if (done(rested, projectile.groundSinceS, projectile.launchTimeS))
        {
            puff(projectile.index);
            removeProjectile(slot);
        }
    }
}

void GameWorld::puff(int index)
{
    const Entity& e = m_entities[static_cast<std::size_t>(index)];
    if (e.body == nullptr)
        return;
    DestroyedEvent event;
    event.kind = EntityKind::Bird;
    event.typeName = e.typeName;
    event.x = e.body->GetPosition().x;
    event.y = e.body->GetPosition().y;
    event.timeS = m_time;
    m_destroyed.push_back(event);
}

void GameWorld::retireAllBirds()
{
    if (m_birdIndex >= 0)
        puff(m_birdIndex);
    for (const Projectile& projectile : m_projectiles)
        puff(projectile.index);
    removeAllBirds();
}

} // namespace abalike
