#pragma once

#include "world/ContactRecorder.hpp"

#include <abalike/world/Catalog.hpp>
#include <abalike/world/Entity.hpp>
#include <abalike/world/WorldSettings.hpp>
#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace abalike
{

/// The bodies of a level's world: the Box2D world, the entities its bodies stand for, the contact recorder, the
/// clock, and what was destroyed since it was last asked. GameWorld's parts act on the world through it.
class WorldBodies
{
public:
    WorldBodies(const LevelDef& level, const Catalog& catalog, const WorldSettings& settings);
    ~WorldBodies();
    WorldBodies(const WorldBodies&) = delete;
    WorldBodies& operator=(const WorldBodies&) = delete;

    /// A new Box2D world holding the level's bodies as designed (also what a settled state is restored onto).
    void build();

    LevelDef& level() { return m_level; }
    const LevelDef& level() const { return m_level; }
    const Catalog& catalog() const { return m_catalog; }
    const WorldSettings& settings() const { return m_settings; }
    b2World& world() { return *m_world; }
    const b2World& world() const { return *m_world; }
    ContactRecorder& contacts() { return *m_contacts; }
    const ContactRecorder& contacts() const { return *m_contacts; }

    std::vector<Entity>& entities() { return m_entities; }
    const std::vector<Entity>& entities() const { return m_entities; }
    Entity& entity(int index) { return m_entities[static_cast<std::size_t>(index)]; }
    const Entity& entity(int index) const { return m_entities[static_cast<std::size_t>(index)]; }
    int addEntity(Entity entity);

    double time() const { return m_time; }
    /// Moves the clock on by one step.
    void tick() { m_time += m_settings.dtS; }

    /// Removes a block or pig: a DestroyedEvent (with its points when scored) and its body is gone.
    void destroyEntity(int index, bool scored, const DefeatCause& cause);
    /// Takes a body out without an event (a bird that leaves).
    void removeBody(int index);
    /// A puff where a bird leaves: a DestroyedEvent of kind Bird with no points.
    void puff(int index);
    std::vector<DestroyedEvent>& destroyed() { return m_destroyed; }
    std::vector<DestroyedEvent> takeDestroyedEvents();

    /// True when the entity's awake body has left the level's extent (beyond its sides or below its floor).
    bool outOfBounds(const Entity& entity) const;
    /// Lightest block or pig as built; 0 when there is none.
    double lightestBodyKg() const { return m_lightestBodyKg; }

    /// See GameWorld::surfaceBelow.
    double surfaceBelow(double x, double fromY) const;
    /// See GameWorld::castCircle; the chord is cast in `pieces` equal parts, as the world's sub-steps move it.
    std::optional<double> castCircle(double radiusM, const FlightState& a, const FlightState& b, int pieces) const;
    bool isSettled() const;
    int pigsAlive() const;
    bool hasNonFiniteState() const;

private:
    void buildLevel();

    LevelDef m_level;
    Catalog m_catalog;
    WorldSettings m_settings;
    std::unique_ptr<b2World> m_world;
    std::unique_ptr<ContactRecorder> m_contacts;
    std::vector<Entity> m_entities;
    std::vector<DestroyedEvent> m_destroyed;
    double m_time = 0.0;
    double m_lightestBodyKg = 0.0;    ///< lightest block or pig at the start; 0 when there is none
    std::array<double, 3> m_extent{}; ///< left, right, bottom: beyond these a body has left the world
};

} // namespace abalike
