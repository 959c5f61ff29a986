#include "level/Outline.hpp"
#include "world/Fixtures.hpp"
#include "world/Skin.hpp"
#include "world/WorldBodies.hpp"

#include <abalike/util/Angles.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace abalike
{

namespace
{

/// Things further than this outside the level's own extent have left the world.
constexpr double kWorldMarginM = 60.0;
/// ... or this far below the ground.
constexpr double kWorldDepthM = 20.0;
/// The ground is a chain of edges of at most this length (Box2D handles static shapes up to ~50 m well).
constexpr double kGroundSegmentM = 40.0;

} // namespace

void WorldBodies::buildLevel()
{
    double minX = m_level.slingshot.x;
    double maxX = m_level.slingshot.x;
    const auto include = [&](double x)
    {
        minX = std::min(minX, x);
        maxX = std::max(maxX, x);
    };
    for (const BlockDef& b : m_level.blocks)
        include(b.x);
    for (const PigDef& p : m_level.pigs)
        include(p.x);
    for (const TerrainDef& t : m_level.terrain)
        include(t.x);
    m_lightestBodyKg = 0.0;
    const auto lightest = [this](double massKg)
    {
        if (m_lightestBodyKg == 0.0 || massKg < m_lightestBodyKg)
            m_lightestBodyKg = massKg;
    };
    const double left = minX - kWorldMarginM;
    const double right = maxX + kWorldMarginM;
    m_extent = {left, right, m_level.groundY - kWorldDepthM};

    // Ground: one chain of edges, listed right to left so its one-sided normal points up.
    {
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
        fixture.friction = static_cast<float>(m_catalog.groundFriction());
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
        def.userData = userDataFor(index);
        b2FixtureDef fixture;
        fixture.friction = static_cast<float>(m_catalog.groundFriction());
        b2Body* body = nullptr;
        if (t.isPolygon())
        {
            // Solid: one fixture per convex piece, in world coordinates. Static pieces need no chamfer (it keeps
            // diagonal neighbours among moving blocks apart) and would notch the surface where pieces meet.
            body = m_world->CreateBody(&def);
            for (const Outline& piece : terrainOutlines(t))
            {
                std::vector<b2Vec2> outline;
                for (const auto& [x, y] : piece.vertices)
                    outline.emplace_back(static_cast<float>(x), static_cast<float>(y));
                addPolygonFixture(body, outline, fixture, 0.0f);
            }
        }
        else
        {
            def.position.Set(static_cast<float>(t.x), static_cast<float>(t.y));
            def.angle = static_cast<float>(t.angleDeg * kDegToRad);
            body = m_world->CreateBody(&def);
            addBoxFixture(body, t.widthM, t.heightM, fixture, static_cast<float>(m_settings.cornerChamferM));
        }
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
        entity.wallM = b.shape == BlockShape::HollowBox ? b.wallM : 0.0;
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
        addBlockFixtures(body, b, fixture, static_cast<float>(m_settings.cornerChamferM));
        setBodyMass(body, material->densityKgPerM2 * designedArea(b));
        lightest(body->GetMass());
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
        fixture.friction = static_cast<float>(type->friction);
        fixture.restitution = static_cast<float>(type->restitution);
        addCircleFixture(body, type->radiusM, fixture);
        setBodyMass(body, type->densityKgPerM2 * std::numbers::pi * type->radiusM * type->radiusM);
        lightest(body->GetMass());
        m_entities[static_cast<std::size_t>(index)].body = body;
    }
}

} // namespace abalike
