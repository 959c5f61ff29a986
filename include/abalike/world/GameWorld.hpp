#pragma once

#include <abalike/flight/FlightIntegrator.hpp>
#include <abalike/flight/Prediction.hpp>
#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Catalog.hpp>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class b2Body;
class b2World;

namespace abalike
{

/// Box2D settings of a world; defaults chosen by measurement (see README, "Physics settings").
struct WorldSettings
{
    double dtS = 1.0 / 60.0;
    int velocityIterations = 8;
    int positionIterations = 3;
};

enum class EntityKind
{
    Ground,
    Terrain,
    Block,
    Pig,
    Bird,
};

/// Something in the world the game cares about. Bodies point back at their entity by index (user data).
struct Entity
{
    EntityKind kind = EntityKind::Block;
    int defIndex = -1;    ///< index in the level's blocks / pigs / terrain, or the shot number for birds
    std::string typeName; ///< material, pig type or bird type
    BlockShape shape = BlockShape::Box;
    double widthM = 0.0;  ///< blocks and terrain: size; pigs and birds: diameter
    double heightM = 0.0;
    double health = 0.0;  ///< remaining impulse it can absorb (N s)
    double maxHealth = 0.0;
    bool alive = true;
    b2Body* body = nullptr; ///< null once removed
};

/// Something that was destroyed during the last steps, for score and effects.
struct DestroyedEvent
{
    EntityKind kind = EntityKind::Block;
    std::string typeName;
    double x = 0.0;
    double y = 0.0;
    int points = 0;
};

/// The Box2D world of a level: builds bodies from the level definition, steps at a fixed rate, turns contact
/// impulses into damage, and flies the launched bird with the flight model until its first contact.
///
/// The bird's free flight is driven by the same FlightIntegrator (RK4) the preview uses: each step the bird's
/// velocity is set to the chord between consecutive RK4 states, so Box2D's own integration and its bullet
/// time-of-impact land exactly where the preview says. At first contact Box2D takes over.
class GameWorld
{
public:
    GameWorld(const LevelDef& level, const Catalog& catalog, const WorldSettings& settings = {});
    ~GameWorld();
    GameWorld(const GameWorld&) = delete;
    GameWorld& operator=(const GameWorld&) = delete;

    /// Advances the world by one fixed step, then applies damage and removes what broke.
    void step();

    double time() const { return m_time; }
    double dt() const { return m_settings.dtS; }
    const WorldSettings& settings() const { return m_settings; }

    /// Puts a bird at s0 and starts its free flight under the model. Returns its entity index.
    int launchBird(const BirdType& bird, const FlightModel& model, const FlightState& s0);
    /// Takes the bird out of the world (it came to rest or left the world).
    void removeBird();
    /// The bird's entity, if one is in the world.
    const Entity* bird() const;
    /// True while the bird has not touched anything since launch.
    bool birdInFreeFlight() const { return m_birdFlight != nullptr; }
    /// Where and when (since launch) the bird first touched something, once it has.
    const std::optional<ContactPoint>& birdContact() const { return m_birdContact; }
    /// The bird's path since launch, one point (t since launch, x, y) per step.
    const std::vector<std::array<double, 3>>& birdPath() const { return m_birdPath; }

    /// Fraction (0..1) along the straight move a -> b at which a circle of the given radius first touches
    /// level geometry, by Box2D's time of impact: the same query the solver runs for bullets.
    std::optional<double> castCircle(double radiusM, const FlightState& a, const FlightState& b) const;

    /// True when every dynamic body is asleep.
    bool isSettled() const;
    int pigsAlive() const;
    /// True if any body has a non-finite position or velocity.
    bool hasNonFiniteState() const;

    const std::vector<Entity>& entities() const { return m_entities; }
    /// Destroyed things since the last call.
    std::vector<DestroyedEvent> takeDestroyedEvents();

    const LevelDef& level() const { return m_level; }
    const Catalog& catalog() const { return m_catalog; }
    b2World& box2d() { return *m_world; }
    const b2World& box2d() const { return *m_world; }

    class ContactRecorder;

private:
    void buildLevel();
    int addEntity(Entity entity);
    void driveBirdFlight();
    void finishBirdStep();
    void applyDamage();
    void removeOutOfBounds();
    void destroyEntity(int index, bool scored);

    LevelDef m_level;
    const Catalog& m_catalog;
    WorldSettings m_settings;
    std::unique_ptr<b2World> m_world;
    std::unique_ptr<ContactRecorder> m_contacts;
    std::vector<Entity> m_entities;
    std::vector<DestroyedEvent> m_destroyed;
    double m_time = 0.0;

    int m_birdIndex = -1;
    double m_birdLaunchTime = 0.0;
    std::unique_ptr<FlightIntegrator> m_birdFlight; ///< drives the bird until its first contact, then null
    std::unique_ptr<FlightIntegrator> m_birdModel;  ///< the same model, evaluated for drag after contact
    FlightState m_birdStepStart{};
    std::optional<ContactPoint> m_birdContact;
    std::vector<std::array<double, 3>> m_birdPath;
};

} // namespace abalike
