#include "world/ContactRecorder.hpp"
#include "world/Skin.hpp"

#include <abalike/world/GameWorld.hpp>

#include <algorithm>
#include <box2d/b2_time_of_impact.h>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace abalike
{

namespace
{

constexpr double kDegToRad = std::numbers::pi / 180.0;

/// Things further than this outside the level's own extent have left the world.
constexpr double kWorldMarginM = 60.0;
/// The ground is a chain of edges of at most this length (Box2D handles static shapes up to ~50 m well).
constexpr double kGroundSegmentM = 40.0;

b2BodyUserData userDataFor(int entityIndex)
{
    b2BodyUserData data;
    data.pointer = static_cast<uintptr_t>(entityIndex + 1);
    return data;
}

void addPolygonFixture(b2Body* body, const std::vector<b2Vec2>& outline, const b2FixtureDef& base)
{
    const std::vector<b2Vec2> core = insetPolygon(outline);
    b2PolygonShape shape;
    shape.Set(core.data(), static_cast<int>(core.size()));
    b2FixtureDef def = base;
    def.shape = &shape;
    body->CreateFixture(&def);
}

void addBoxFixture(b2Body* body, double w, double h, const b2FixtureDef& base)
{
    const auto hw = static_cast<float>(w / 2);
    const auto hh = static_cast<float>(h / 2);
    addPolygonFixture(body, {{-hw, -hh}, {hw, -hh}, {hw, hh}, {-hw, hh}}, base);
}

void addCircleFixture(b2Body* body, double radius, const b2FixtureDef& base)
{
    b2CircleShape circle;
    circle.m_radius = physicsCircleRadius(radius);
    b2FixtureDef def = base;
    def.shape = &circle;
    body->CreateFixture(&def);
}

} // namespace

GameWorld::GameWorld(const LevelDef& level, const Catalog& catalog, const WorldSettings& settings)
    : m_level(level), m_catalog(catalog), m_settings(settings)
{
    if (!(settings.dtS > 0.0) || !std::isfinite(settings.dtS))
        throw std::invalid_argument("world time step must be a finite number > 0");
    m_world = std::make_unique<b2World>(b2Vec2(0.0f, static_cast<float>(-level.environment.gravity)));
    m_contacts = std::make_unique<ContactRecorder>(static_cast<float>(catalog.damageSpeedThresholdMps()));
    m_world->SetContactListener(m_contacts.get());
    buildLevel();
}

GameWorld::~GameWorld()
{
    // The listener must not see the bodies being destroyed with the world.
    m_world->SetContactListener(nullptr);
}

int GameWorld::addEntity(Entity entity)
{
    m_entities.push_back(std::move(entity));
    return static_cast<int>(m_entities.size()) - 1;
}

void GameWorld::buildLevel()
{
    // Ground: one chain of edges, listed right to left so its one-sided normal points up.
    double minX = m_level.slingshot.x;
    double maxX = m_level.slingshot.x;
    for (const BlockDef& b : m_level.blocks)
    {
        minX = std::min(minX, b.x);
        maxX = std::max(maxX, b.x);
    }
    for (const PigDef& p : m_level.pigs)
    {
        minX = std::min(minX, p.x);
        maxX = std::max(maxX, p.x);
    }
    for (const TerrainDef& t : m_level.terrain)
    {
        minX = std::min(minX, t.x);
        maxX = std::max(maxX, t.x);
    }
    {
        const double left = minX - kWorldMarginM;
        const double right = maxX + kWorldMarginM;
        const int segments = std::max(1, static_cast<int>(std::ceil((right - left) / kGroundSegmentM)));
        std::vector<b2Vec2> points;
        for (int i = segments; i >= 0; --i)
            points.emplace_back(static_cast<float>(left + (right - left) * i / segments),
                                static_cast<float>(m_level.groundY) - kPolygonInset);
        b2ChainShape chain;
        chain.CreateChain(points.data(), static_cast<int>(points.size()), points.front() + b2Vec2(1.0f, 0.0f),
                          points.back() - b2Vec2(1.0f, 0.0f));
        Entity ground;
        ground.kind = EntityKind::Ground;
        ground.widthM = right - left;
        const int index = addEntity(ground);
        b2BodyDef def;
        def.userData = userDataFor(index);
        b2Body* body = m_world->CreateBody(&def);
        b2FixtureDef fixture;
        fixture.shape = &chain;
        fixture.friction = 0.8f;
        body->CreateFixture(&fixture);
        m_entities[static_cast<std::size_t>(index)].body = body;
    }

    for (std::size_t i = 0; i < m_level.terrain.size(); ++i)
    {
        const TerrainDef& t = m_level.terrain[i];
        Entity entity;
        entity.kind = EntityKind::Terrain;
        entity.defIndex = static_cast<int>(i);
        entity.widthM = t.widthM;
        entity.heightM = t.heightM;
        const int index = addEntity(entity);
        b2BodyDef def;
        def.position.Set(static_cast<float>(t.x), static_cast<float>(t.y));
        def.angle = static_cast<float>(t.angleDeg * kDegToRad);
        def.userData = userDataFor(index);
        b2Body* body = m_world->CreateBody(&def);
        b2FixtureDef fixture;
        fixture.friction = 0.8f;
        addBoxFixture(body, t.widthM, t.heightM, fixture);
        m_entities[static_cast<std::size_t>(index)].body = body;
    }

    for (std::size_t i = 0; i < m_level.blocks.size(); ++i)
    {
        const BlockDef& b = m_level.blocks[i];
        const Material* material = m_catalog.findMaterial(b.material);
        if (material == nullptr)
            throw std::invalid_argument("unknown material \"" + b.material + "\"");
        Entity entity;
        entity.kind = EntityKind::Block;
        entity.defIndex = static_cast<int>(i);
        entity.typeName = b.material;
        entity.shape = b.shape;
        entity.widthM = b.widthM;
        entity.heightM = b.heightM;
        entity.health = entity.maxHealth = material->strengthNs;
        const int index = addEntity(entity);

        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(static_cast<float>(b.x), static_cast<float>(b.y));
        def.angle = static_cast<float>(b.angleDeg * kDegToRad);
        def.userData = userDataFor(index);
        b2Body* body = m_world->CreateBody(&def);
        b2FixtureDef fixture;
        fixture.density = static_cast<float>(material->densityKgPerM2);
        fixture.friction = static_cast<float>(material->friction);
        fixture.restitution = static_cast<float>(material->restitution);
        const auto hw = static_cast<float>(b.widthM / 2);
        const auto hh = static_cast<float>(b.heightM / 2);
        switch (b.shape)
        {
        case BlockShape::Box:
            addBoxFixture(body, b.widthM, b.heightM, fixture);
            break;
        case BlockShape::Circle:
            addCircleFixture(body, b.widthM / 2, fixture);
            break;
        case BlockShape::Triangle:
            addPolygonFixture(body, {{-hw, -hh}, {hw, -hh}, {-hw, hh}}, fixture);
            break;
        }
        m_entities[static_cast<std::size_t>(index)].body = body;
    }

    for (std::size_t i = 0; i < m_level.pigs.size(); ++i)
    {
        const PigDef& p = m_level.pigs[i];
        const PigType* type = m_catalog.findPig(p.type);
        if (type == nullptr)
            throw std::invalid_argument("unknown pig type \"" + p.type + "\"");
        Entity entity;
        entity.kind = EntityKind::Pig;
        entity.defIndex = static_cast<int>(i);
        entity.typeName = p.type;
        entity.shape = BlockShape::Circle;
        entity.widthM = entity.heightM = 2.0 * type->radiusM;
        entity.health = entity.maxHealth = type->healthNs;
        const int index = addEntity(entity);

        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(static_cast<float>(p.x), static_cast<float>(p.y));
        def.angularDamping = 1.0f; // pigs roll to a stop instead of forever
        def.userData = userDataFor(index);
        b2Body* body = m_world->CreateBody(&def);
        b2FixtureDef fixture;
        fixture.density = static_cast<float>(type->densityKgPerM2);
        fixture.friction = 0.6f;
        fixture.restitution = 0.2f;
        addCircleFixture(body, type->radiusM, fixture);
        m_entities[static_cast<std::size_t>(index)].body = body;
    }
}

int GameWorld::launchBird(const BirdType& bird, const FlightModel& model, const FlightState& s0)
{
    removeBird();
    Entity entity;
    entity.kind = EntityKind::Bird;
    entity.typeName = bird.name;
    entity.shape = BlockShape::Circle;
    entity.widthM = entity.heightM = 2.0 * bird.radiusM;
    m_birdIndex = addEntity(entity);

    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.bullet = true; // continuous collision against everything, so fast birds never pass through
    def.position.Set(static_cast<float>(s0[0]), static_cast<float>(s0[1]));
    def.linearVelocity.Set(static_cast<float>(s0[2]), static_cast<float>(s0[3]));
    def.gravityScale = 0.0f; // in free flight the flight model supplies every force
    def.angularDamping = 0.8f;
    def.userData = userDataFor(m_birdIndex);
    b2Body* body = m_world->CreateBody(&def);
    b2FixtureDef fixture;
    const double r = physicsCircleRadius(bird.radiusM);
    fixture.density = static_cast<float>(bird.massKg / (std::numbers::pi * r * r)); // mass exactly the bird's
    fixture.friction = 0.6f;
    fixture.restitution = 0.3f;
    addCircleFixture(body, bird.radiusM, fixture);
    m_entities[static_cast<std::size_t>(m_birdIndex)].body = body;

    IntegratorSettings flightSettings;
    flightSettings.stepper = StepperKind::Rk4;
    flightSettings.dtS = m_settings.dtS;
    m_birdFlight = std::make_unique<FlightIntegrator>(model, flightSettings);
    m_birdFlight->reset(0.0, s0);
    m_birdModel = std::make_unique<FlightIntegrator>(model, flightSettings);
    m_birdLaunchTime = m_time;
    m_birdContact.reset();
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

const Entity* GameWorld::bird() const
{
    return m_birdIndex >= 0 ? &m_entities[static_cast<std::size_t>(m_birdIndex)] : nullptr;
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
    // After first contact Box2D owns the bird; the flight model's forces other than gravity (which the world
    // applies) still act on it: drag and wind, from the same right-hand side.
    const b2Vec2 p = body->GetPosition();
    const b2Vec2 v = body->GetLinearVelocity();
    const FlightState s{p.x, p.y, v.x, v.y};
    const FlightState dsdt = m_birdModel->rightHandSide(m_time - m_birdLaunchTime, s);
    const double gravity = m_birdModel->model().gravity;
    const double mass = body->GetMass();
    body->ApplyForceToCenter(b2Vec2(static_cast<float>(mass * dsdt[2]), static_cast<float>(mass * (dsdt[3] + gravity))),
                             true);
}

void GameWorld::finishBirdStep()
{
    b2Body* body = m_entities[static_cast<std::size_t>(m_birdIndex)].body;
    const double sinceLaunch = m_time - m_birdLaunchTime;
    if (m_birdFlight && m_contacts->birdTouch())
    {
        // The touch happened on this step's chord: its time is the fraction of the chord travelled.
        const b2Vec2 touch = *m_contacts->birdTouch();
        const double dx = m_birdFlight->state()[0] - m_birdStepStart[0];
        const double dy = m_birdFlight->state()[1] - m_birdStepStart[1];
        const double length2 = dx * dx + dy * dy;
        double fraction = 1.0;
        if (length2 > 0.0)
            fraction = std::clamp(((touch.x - m_birdStepStart[0]) * dx + (touch.y - m_birdStepStart[1]) * dy) / length2,
                                  0.0, 1.0);
        const double t = sinceLaunch - m_settings.dtS + fraction * m_settings.dtS;
        m_birdContact = ContactPoint{t, touch.x, touch.y};
        m_birdPath.push_back({t, touch.x, touch.y});
        m_birdFlight.reset();
        body->SetGravityScale(1.0f);
    }
    const b2Vec2 p = body->GetPosition();
    m_birdPath.push_back({sinceLaunch, p.x, p.y});
}

void GameWorld::step()
{
    m_contacts->clearStep();
    if (m_birdIndex >= 0)
        driveBirdFlight();
    m_world->Step(static_cast<float>(m_settings.dtS), m_settings.velocityIterations, m_settings.positionIterations);
    m_time += m_settings.dtS;
    if (m_birdIndex >= 0)
        finishBirdStep();
    applyDamage();
    removeOutOfBounds();
}

void GameWorld::applyDamage()
{
    // Process in index order so results never depend on hash-map iteration order.
    std::vector<std::pair<int, double>> hits(m_contacts->impulses().begin(), m_contacts->impulses().end());
    std::sort(hits.begin(), hits.end());
    for (const auto& [index, impulse] : hits)
    {
        Entity& entity = m_entities[static_cast<std::size_t>(index)];
        if (!entity.alive || (entity.kind != EntityKind::Block && entity.kind != EntityKind::Pig))
            continue;
        entity.health -= impulse;
        if (entity.health <= 0.0)
            destroyEntity(index, true);
    }
}

void GameWorld::removeOutOfBounds()
{
    double minX = m_level.slingshot.x;
    double maxX = m_level.slingshot.x;
    for (const BlockDef& b : m_level.blocks)
        maxX = std::max(maxX, b.x), minX = std::min(minX, b.x);
    for (const PigDef& p : m_level.pigs)
        maxX = std::max(maxX, p.x), minX = std::min(minX, p.x);
    const double left = minX - kWorldMarginM;
    const double right = maxX + kWorldMarginM;
    const double bottom = m_level.groundY - 20.0;
    for (std::size_t i = 0; i < m_entities.size(); ++i)
    {
        Entity& e = m_entities[i];
        if (!e.alive || e.body == nullptr || e.body->GetType() != b2_dynamicBody)
            continue;
        const b2Vec2 p = e.body->GetPosition();
        if (p.x >= left && p.x <= right && p.y >= bottom)
            continue;
        if (e.kind == EntityKind::Bird)
            removeBird();
        else
            destroyEntity(static_cast<int>(i), e.kind == EntityKind::Pig); // a pig off the world is defeated
    }
}

void GameWorld::destroyEntity(int index, bool scored)
{
    Entity& e = m_entities[static_cast<std::size_t>(index)];
    if (!e.alive)
        return;
    DestroyedEvent event;
    event.kind = e.kind;
    event.typeName = e.typeName;
    if (e.body != nullptr)
    {
        event.x = e.body->GetPosition().x;
        event.y = e.body->GetPosition().y;
        m_world->DestroyBody(e.body);
    }
    if (scored)
    {
        if (e.kind == EntityKind::Block)
            event.points = m_catalog.findMaterial(e.typeName)->points;
        else if (e.kind == EntityKind::Pig)
            event.points = m_catalog.findPig(e.typeName)->points;
    }
    e.body = nullptr;
    e.alive = false;
    e.health = 0.0;
    m_destroyed.push_back(event);
}

std::vector<DestroyedEvent> GameWorld::takeDestroyedEvents()
{
    std::vector<DestroyedEvent> events;
    events.swap(m_destroyed);
    return events;
}

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
        const b2Body* skip = nullptr;
        bool ReportFixture(b2Fixture* fixture) override
        {
            if (fixture->GetBody() != skip && !fixture->IsSensor())
                fixtures.push_back(fixture);
            return true;
        }
    } query;
    query.skip = m_birdIndex >= 0 ? m_entities[static_cast<std::size_t>(m_birdIndex)].body : nullptr;
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

bool GameWorld::isSettled() const
{
    for (const b2Body* body = m_world->GetBodyList(); body != nullptr; body = body->GetNext())
        if (body->GetType() == b2_dynamicBody && body->IsAwake())
            return false;
    return true;
}

int GameWorld::pigsAlive() const
{
    return static_cast<int>(std::count_if(m_entities.begin(), m_entities.end(), [](const Entity& e) {
        return e.kind == EntityKind::Pig && e.alive;
    }));
}

bool GameWorld::hasNonFiniteState() const
{
    for (const b2Body* body = m_world->GetBodyList(); body != nullptr; body = body->GetNext())
    {
        const b2Vec2 p = body->GetPosition();
        const b2Vec2 v = body->GetLinearVelocity();
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(v.x) || !std::isfinite(v.y) ||
            !std::isfinite(body->GetAngle()) || !std::isfinite(body->GetAngularVelocity()))
            return true;
    }
    return false;
}

} // namespace abalike
