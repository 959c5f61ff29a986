#include "render/WorldRenderer.hpp"

#include "render/AbilityLook.hpp"
#include "render/Backdrop.hpp"
#include "render/BlockPainter.hpp"
#include "render/CharacterPainter.hpp"
#include "render/ConvexPolygon.hpp"
#include "render/Palette.hpp"
#include "render/SlingshotPainter.hpp"

#include <abalike/level/PolygonPartition.hpp>
#include <algorithm>
#include <box2d/box2d.h>
#include <numbers>
#include <vector>

namespace abalike::app
{

namespace
{
constexpr float kRadToDeg = 180.0f / std::numbers::pi_v<float>;
constexpr float kWaitingGapM = 0.1f;

sf::Transform bodyTransform(const b2Body& body)
{
    sf::Transform transform;
    transform.translate(body.GetPosition().x, body.GetPosition().y).rotate(body.GetAngle() * kRadToDeg);
    return transform;
}

/// A bird in the air faces where it goes, upright: turned to its velocity, mirrored when it flies leftwards (its
/// drawing faces +x). Slower than this, or while it touches something (it rolls and tumbles), it keeps its body's
/// angle.
constexpr float kFacingSpeedMps = 0.5f;

bool touchesAnything(const b2Body& body)
{
    for (const b2ContactEdge* edge = body.GetContactList(); edge != nullptr; edge = edge->next)
        if (edge->contact->IsTouching())
            return true;
    return false;
}

sf::Transform facingTransform(const b2Body& body)
{
    const b2Vec2 v = body.GetLinearVelocity();
    sf::Transform transform;
    transform.translate(body.GetPosition().x, body.GetPosition().y);
    if (v.x >= 0.0f)
        transform.rotate(std::atan2(v.y, v.x) * kRadToDeg);
    else
        transform.rotate(std::atan2(-v.y, -v.x) * kRadToDeg).scale(-1.0f, 1.0f);
    return transform;
}

sf::Transform placeAt(sf::Vector2f position)
{
    sf::Transform transform;
    transform.translate(position);
    return transform;
}

float healthFraction(const Entity& entity)
{
    if (entity.maxHealth <= 0.0)
        return 1.0f;
    return static_cast<float>(std::clamp(entity.health / entity.maxHealth, 0.0, 1.0));
}

/// The catalog's bird of a type; a level's birds are checked against the catalog when it loads.
const BirdType& birdOf(const Catalog& catalog, const std::string& type)
{
    static const BirdType unknown;
    const BirdType* bird = catalog.findBird(type);
    return bird != nullptr ? *bird : unknown;
}

std::vector<sf::Vector2f> polygonPoints(const b2PolygonShape& shape)
{
    std::vector<sf::Vector2f> points;
    points.reserve(static_cast<std::size_t>(shape.m_count));
    for (int i = 0; i < shape.m_count; ++i)
        points.emplace_back(shape.m_vertices[i].x, shape.m_vertices[i].y);
    return points;
}
} // namespace

void WorldRenderer::drawBackground(sf::RenderTarget& target, const Camera& camera, const GameSession& session)
{
    const auto groundY = static_cast<float>(session.level().groundY);
    m_base.clear();
    m_mesh.clear();
    m_base.setPixelSize(camera.metresPerPixel());
    m_mesh.setPixelSize(camera.metresPerPixel());
    const Scenery& scenery = sceneryOf(levelTheme(session.level()));
    m_surface = scenery.surface; // the terrain's top edges wear the world's surface too
    Backdrop::paint(m_base, m_mesh, camera, groundY, scenery);
    for (const Entity& entity : session.world().entities())
    {
        if (entity.alive && entity.body != nullptr && entity.kind == EntityKind::Terrain)
        {
            const TerrainDef& def = session.level().terrain[static_cast<std::size_t>(entity.defIndex)];
            if (def.isPolygon())
                addTerrainPolygon(entity, def, camera.metresPerPixel());
            else
                addTerrain(entity, camera.metresPerPixel());
        }
    }
    m_base.draw(target, camera.transform(), sf::BlendNone);
    m_mesh.draw(target, camera.transform());
}

void WorldRenderer::drawForeground(sf::RenderTarget& target, const Camera& camera, const GameSession& session,
                                   sf::Vector2f pullOffset)
{
    const LevelDef& level = session.level();
    const float pixelM = camera.metresPerPixel();
    const std::vector<Entity>& entities = session.world().entities();
    m_mesh.clear();
    m_mesh.setPixelSize(pixelM);

    // The slingshot and the bird it holds.
    const Vec2 pouch = session.launchPoint();
    SlingshotPose pose;
    // The slingshot stands on whatever is under it: a cliff or a hill top, else the ground.
    const auto standY = static_cast<float>(standingY(session.world(), level.slingshot.x, pouch.y));
    pose.base = {static_cast<float>(level.slingshot.x), standY};
    pose.pouch = {static_cast<float>(pouch.x), static_cast<float>(pouch.y)};
    const BirdType* loaded = session.phase() == Phase::Aiming ? session.currentBird() : nullptr;
    if (loaded != nullptr)
    {
        pose.birdRadius = static_cast<float>(loaded->radiusM);
        pose.loadedBird = loadedBirdAt(session, pullOffset);
    }
    addWaitingBirds(session, pixelM);
    SlingshotPainter::paintBack(m_mesh, pose, pixelM);
    if (loaded != nullptr)
    {
        m_mesh.setLocalTransform(placeAt(*pose.loadedBird));
        CharacterPainter::paintBird(m_mesh, *loaded, pose.birdRadius, pixelM);
        m_mesh.resetLocalTransform();
    }
    SlingshotPainter::paintFront(m_mesh, pose, pixelM);

    for (std::size_t i = 0; i < entities.size(); ++i)
    {
        const Entity& entity = entities[i];
        if (!entity.alive || entity.body == nullptr)
            continue;
        if (entity.kind == EntityKind::Block)
            addBlock(entity, session.catalog(), i, pixelM);
        else if (entity.kind == EntityKind::Pig)
            addPig(entity, session.catalog(), pixelM);
    }
    updateDazed(session);
    for (std::size_t i = 0; i < entities.size(); ++i)
    {
        const Entity& entity = entities[i];
        if (entity.alive && entity.body != nullptr && entity.kind == EntityKind::Bird)
        {
            addBird(entity, session.catalog(), i, pixelM);
            addOffscreenMarker(entity, session.catalog(), camera);
        }
    }
    m_mesh.draw(target, camera.transform());
}

std::optional<sf::Vector2f> WorldRenderer::loadedBirdAt(const GameSession& session, sf::Vector2f pullOffset)
{
    const BirdType* loaded = session.phase() == Phase::Aiming ? session.currentBird() : nullptr;
    if (loaded == nullptr)
        return std::nullopt;
    const Vec2 pouch = session.launchPoint();
    const auto standY = static_cast<float>(standingY(session.world(), session.level().slingshot.x, pouch.y));
    sf::Vector2f seat = sf::Vector2f(static_cast<float>(pouch.x), static_cast<float>(pouch.y)) + pullOffset;
    seat.y = std::max(seat.y, standY + static_cast<float>(loaded->radiusM));
    return seat;
}

void WorldRenderer::addTerrain(const Entity& entity, float pixelM)
{
    m_mesh.setLocalTransform(bodyTransform(*entity.body));
    for (const b2Fixture* fixture = entity.body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext())
    {
        if (fixture->GetType() != b2Shape::e_polygon)
            continue;
        const std::vector<sf::Vector2f> points =
            polygonPoints(*static_cast<const b2PolygonShape*>(fixture->GetShape()));
        const std::vector<sf::Vector2f> inner = convex::inset(points, std::max(0.05f, 2.0f * pixelM));
        m_mesh.addConvex(points, palette::kTerrainEdge);
        m_mesh.addConvex(inner.empty() ? points : inner, palette::kTerrain);
    }
    m_mesh.resetLocalTransform();
}

void WorldRenderer::addTerrainPolygon(const Entity& entity, const TerrainDef& def, float pixelM)
{
    // The designed convex pieces (not the world's, which are inset for Box2D's skin and would show seams), then
    // the outline and the grass along the polygon as designed. Terrain never moves: world coordinates.
    (void)entity;
    for (const std::vector<Vec2>& piece : convexPieces(def.points))
    {
        std::vector<sf::Vector2f> corners;
        for (const auto& [x, y] : piece)
            corners.emplace_back(static_cast<float>(x), static_cast<float>(y));
        m_mesh.addConvex(corners, palette::kTerrain);
    }
    std::vector<sf::Vector2f> points;
    for (const auto& [x, y] : def.points)
        points.emplace_back(static_cast<float>(x), static_cast<float>(y));
    float twiceArea = 0.0f;
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        const sf::Vector2f& a = points[i];
        const sf::Vector2f& b = points[(i + 1) % points.size()];
        twiceArea += a.x * b.y - b.x * a.y;
    }
    const float outward = twiceArea > 0.0f ? 1.0f : -1.0f; // counter-clockwise: the outside is to the right
    const float edge = std::max(0.05f, 2.0f * pixelM);
    const float grass = std::max(0.12f, 5.0f * pixelM);
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        const sf::Vector2f& a = points[i];
        const sf::Vector2f& b = points[(i + 1) % points.size()];
        const sf::Vector2f d = b - a;
        const float length = std::hypot(d.x, d.y);
        if (length <= 0.0f)
            continue;
        const sf::Vector2f normal = outward * sf::Vector2f(d.y, -d.x) / length;
        m_mesh.addLine(a, b, edge, palette::kTerrainEdge);
        if (normal.y > 0.5f) // a top edge: grass, drawn just inside the surface
        {
            const sf::Vector2f in = -normal * (0.5f * grass);
            m_mesh.addLine(a + in, b + in, grass, m_surface);
        }
    }
}

void WorldRenderer::addBlock(const Entity& entity, const Catalog& catalog, std::size_t index, float pixelM)
{
    static const MaterialLook unknown;
    const Material* material = catalog.findMaterial(entity.typeName);
    BlockLook look;
    look.material = material != nullptr ? &material->look : &unknown;
    look.healthFraction = healthFraction(entity);
    look.pixelM = pixelM;
    m_mesh.setLocalTransform(bodyTransform(*entity.body));
    std::uint64_t fixtureNumber = 0;
    for (const b2Fixture* fixture = entity.body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext())
    {
        look.seed = index * 131u + fixtureNumber++;
        if (fixture->GetType() == b2Shape::e_polygon)
        {
            const auto& shape = *static_cast<const b2PolygonShape*>(fixture->GetShape());
            BlockPainter::paintPolygon(m_mesh, polygonPoints(shape), look);
        }
        else if (fixture->GetType() == b2Shape::e_circle)
        {
            const auto& shape = *static_cast<const b2CircleShape*>(fixture->GetShape());
            BlockPainter::paintDisc(m_mesh, {shape.m_p.x, shape.m_p.y}, shape.m_radius, look);
        }
    }
    m_mesh.resetLocalTransform();
}

void WorldRenderer::addPig(const Entity& entity, const Catalog& catalog, float pixelM)
{
    const PigType* type = catalog.findPig(entity.typeName);
    m_mesh.setLocalTransform(bodyTransform(*entity.body));
    CharacterPainter::paintPig(m_mesh, static_cast<float>(0.5 * entity.widthM), type != nullptr && type->helmet,
                               healthFraction(entity), pixelM);
    m_mesh.resetLocalTransform();
}

void WorldRenderer::updateDazed(const GameSession& session)
{
    const GameWorld& world = session.world();
    // A new world, or the same one started again (its clock went back), has no dazed birds yet.
    if (&world != m_dazedWorld || world.time() < m_dazedTimeS)
        m_dazed.clear();
    m_dazedWorld = &world;
    m_dazedTimeS = world.time();
    const std::vector<Entity>& entities = world.entities();
    m_dazed.resize(entities.size(), false);
    for (std::size_t i = 0; i < entities.size(); ++i)
    {
        const Entity& entity = entities[i];
        if (m_dazed[i] || entity.kind != EntityKind::Bird || entity.body == nullptr)
            continue;
        for (const b2ContactEdge* edge = entity.body->GetContactList(); edge != nullptr; edge = edge->next)
            if (edge->contact->IsTouching())
                m_dazed[i] = true;
    }
}

void WorldRenderer::addBird(const Entity& entity, const Catalog& catalog, std::size_t index, float pixelM)
{
    const auto mood = index < m_dazed.size() && m_dazed[index] ? CharacterPainter::BirdMood::Dazed
                                                               : CharacterPainter::BirdMood::Angry;
    const bool flying = entity.body->GetLinearVelocity().Length() > kFacingSpeedMps && !touchesAnything(*entity.body);
    m_mesh.setLocalTransform(flying ? facingTransform(*entity.body) : bodyTransform(*entity.body));
    // A body an ability added may have a look of its own (an egg); the rest are birds of their type.
    if (entity.madeBy == nullptr || !abilityLook(entity.madeBy->name()).paintBody(m_mesh, entity, pixelM))
        CharacterPainter::paintBird(m_mesh, birdOf(catalog, entity.typeName), static_cast<float>(0.5 * entity.widthM),
                                    pixelM, mood);
    m_mesh.resetLocalTransform();
}

double WorldRenderer::standingY(const GameWorld& world, double x, double fromY)
{
    const LevelDef& level = world.level();
    if (level.terrain != m_standTerrain || level.groundY != m_standGroundY)
    {
        m_standTerrain = level.terrain;
        m_standGroundY = level.groundY;
        m_standCache.clear();
    }
    for (const auto& [cachedX, cachedFrom, y] : m_standCache)
        if (cachedX == x && cachedFrom == fromY)
            return y;
    const double y = world.surfaceBelow(x, fromY);
    m_standCache.push_back({x, fromY, y});
    return y;
}

void WorldRenderer::addWaitingBirds(const GameSession& session, float pixelM)
{
    // Birds not yet launched line up left of the slingshot on whatever is under each (the cliff top it stands on,
    // else the ground); while aiming, the first of them is the one in the pouch.
    const LevelDef& level = session.level();
    const int first = session.birdsUsed() + (session.phase() == Phase::Aiming ? 1 : 0);
    float x = static_cast<float>(level.slingshot.x) - 1.1f;
    for (int i = first; i < static_cast<int>(level.birds.size()); ++i)
    {
        const std::string& type = level.birds[static_cast<std::size_t>(i)];
        const BirdType& bird = birdOf(session.catalog(), type);
        const auto radius = static_cast<float>(bird.radiusM);
        x -= radius;
        const double standY = standingY(session.world(), x, session.launchPoint().y);
        m_mesh.setLocalTransform(placeAt({x, static_cast<float>(standY) + radius}));
        CharacterPainter::paintBird(m_mesh, bird, radius, pixelM);
        x -= radius + kWaitingGapM + 0.3f * radius; // room for the tail feathers
    }
    m_mesh.resetLocalTransform();
}

void WorldRenderer::addOffscreenMarker(const Entity& bird, const Catalog& catalog, const Camera& camera)
{
    // Above the top of the view, show an arrow at the edge so the player can follow the bird.
    const sf::FloatRect view = camera.visibleWorld();
    const float top = view.top + view.height;
    const b2Vec2 position = bird.body->GetPosition();
    if (position.y - 0.5f * static_cast<float>(bird.widthM) <= top)
        return;
    const float size = 10.0f * camera.metresPerPixel();
    const float x = std::clamp(position.x, view.left + size, view.left + view.width - size);
    const float y = top - 0.4f * size;
    m_mesh.addTriangle({x - size, y - 1.5f * size}, {x, y}, {x + size, y - 1.5f * size},
                       birdColours(birdOf(catalog, bird.typeName).look).body);
}

} // namespace abalike::app
