#pragma once

#include <abalike/flight/FlightIntegrator.hpp>
#include <abalike/flight/Prediction.hpp>
#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Ability.hpp>
#include <abalike/world/BirdBody.hpp>
#include <abalike/world/Catalog.hpp>
#include <abalike/world/FirstImpact.hpp>
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class b2Body;
class b2World;

namespace abalike
{

struct SettledState;

/// Box2D settings of a world; the defaults were chosen by measurement (docs/world-physics.md, "Iterations").
struct WorldSettings
{
    double dtS = 1.0 / 60.0;
    int velocityIterations = 8;
    int positionIterations = 3;
    /// A step is split into up to this many Box2D sub-steps so that no body moves more than 90 % of
    /// b2_maxTranslation (2 m) per sub-step; Box2D would otherwise silently cap speeds at 2 m / dt (120 m/s at
    /// 60 Hz). 1 turns sub-stepping off.
    int maxSubsteps = 8;
    bool allowSleep = true;
    /// Velocity iterations of the very first step. Box2D warm-starts each step from the last step's contact
    /// impulses; a level starts with none, and with 8 iterations the top of a 20-block tower falls 10 cm before
    /// the impulses build up. Solving the first step well makes them right from the start (measured in
    /// docs/world-physics.md). kAutoSettle: 5 x depth^2 (at least 2000, at most 10 000), depth being the most
    /// bodies stacked on each other, because Gauss-Seidel needs about depth^2 sweeps to carry the load of the top
    /// body down to the ground; 0: no settle step; more: that many.
    int settleIterations = kAutoSettle;
    /// Box2D sub-steps per step for the level's stacks: ceil(depth / stackDepthPerSubstep), at most
    /// maxStackSubsteps, depth being the most bodies resting on each other (stackDepth()). Sequential impulses
    /// hold a deep stack only approximately; the error grows with depth and shrinks with the sub-step, and a tall
    /// column under an off-centre load leans a little more every step unless the sub-step is short enough
    /// (docs/world-physics.md, "Walls and mixed towers"). 1 turns it off.
    int stackDepthPerSubstep = 5;
    int maxStackSubsteps = 4;
    /// Corners of polygon cores are cut by this much (m) so that blocks meeting only corner to corner, such as
    /// diagonal neighbours in a wall, do not touch (Skin.hpp); 0 turns it off.
    double cornerChamferM = 0.003;
    /// A contact between two bodies (birds aside) acts only once their designed surfaces are closer than this (m).
    /// Box2D makes every contact within its 1 cm skin rigid, which would let a pig near the edge of a block lean
    /// on the rounded corner of the next one, 2 mm away; negative turns it off.
    double contactGapM = 0.001;
    /// Rolling resistance for pigs and round blocks (the catalog's "rolling" coefficient); false turns it off.
    bool rollingResistance = true;
    /// Break-through (GameWorld::refundBreakingContacts): a body that breaks absorbs only its remaining strength and
    /// whatever struck it keeps the rest of its momentum. false keeps Box2D's impulse as solved, as if the broken
    /// body had been unbreakable for that step (the rule before; tests and `bench feel` compare the two).
    bool breakThrough = true;
    /// Reuse settle steps (SettleCache): a world whose bodies and settings match one settled before starts from its
    /// state. Either way the settled state passes through the same restore, so results do not depend on the cache;
    /// false solves the settle step in place as Box2D leaves it (benchmarks that time it or compare with raw Box2D).
    bool settleCache = true;

    static constexpr int kAutoSettle = -1;
};

enum class EntityKind
{
    Ground,
    Terrain,
    Block,
    Pig,
    Bird, ///< the launched bird, the extra birds of a split and eggs (typeName "egg")
};

/// The name of a kind in simulate's JSON and reports ("ground", "terrain", "block", "pig", "bird").
const char* entityKindName(EntityKind kind);

/// Something in the world the game cares about. Bodies point back at their entity by index (user data).
struct Entity
{
    EntityKind kind = EntityKind::Block;
    int defIndex = -1;    ///< index in the level's blocks / pigs / terrain, or the shot number for birds
    std::string typeName; ///< material, pig type or bird type
    BlockShape shape = BlockShape::Box;
    double widthM = 0.0; ///< blocks and terrain: size; pigs and birds: diameter
    double heightM = 0.0;
    double wallM = 0.0;  ///< hollow boxes: wall thickness
    double health = 0.0; ///< remaining impulse it can absorb (N s)
    double maxHealth = 0.0;
    bool alive = true;
    b2Body* body = nullptr; ///< null once removed; built anew by the first step (GameWorld::box2d)
};

/// What broke a block or defeated a pig: the body that delivered the largest impulse in the step in which its
/// health reached zero, or the event that removed it.
enum class CauseKind
{
    Bird,        ///< the shot's bird or one of its split birds
    Block,       ///< a block (falling, sliding, thrown)
    Pig,         ///< a pig
    Explosion,   ///< the black bird's blast or a TNT crate's
    Egg,         ///< the white bird's egg
    Ground,      ///< the ground or terrain
    OutOfBounds, ///< it left the level's bounds
};

/// The name a cause has in simulate's JSON and play's trace ("bird", "block", ... "out_of_bounds").
const char* causeKindName(CauseKind kind);

struct DefeatCause
{
    CauseKind kind = CauseKind::Bird;
    int index = -1; ///< for Block and Pig: its index in the level's blocks or pigs; -1 otherwise
};

/// Something that was destroyed or left the world during the last steps, for score, effects and the defeat record.
/// Birds that retire after their shot appear too (kind Bird, 0 points): the game shows a puff there.
struct DestroyedEvent
{
    EntityKind kind = EntityKind::Block;
    std::string typeName;
    double x = 0.0;
    double y = 0.0;
    int points = 0;
    int index = -1;   ///< blocks and pigs: index in the level's blocks or pigs
    double timeS = 0; ///< world time (s since the level started)
    DefeatCause cause;
    int shot = -1; ///< the shot under way (from 0; -1 before the first launch); set by GameSession
};

/// A TNT crate that exploded: where and when, and what its blast pushed.
struct BlastEvent
{
    double timeS = 0.0;
    double x = 0.0;
    double y = 0.0;
    double radiusM = 0.0;
    int blockIndex = -1; ///< the crate's index in the level's blocks
};

/// The Box2D world of a level: builds bodies from the level definition, steps at a fixed rate, turns contact
/// impulses into damage, and flies the launched bird with the flight model until its first contact.
///
/// The bird's free flight is driven by the same FlightIntegrator (RK4) the preview uses: each step the bird's
/// velocity is set to the chord between consecutive RK4 states, so Box2D's own integration and its bullet
/// time-of-impact land exactly where the preview says. At first contact Box2D takes over. An ability that
/// changes the bird's velocity in flight re-seeds the integrator from the new state.
class GameWorld
{
public:
    GameWorld(const LevelDef& level, const Catalog& catalog, const WorldSettings& settings = {});
    ~GameWorld();
    GameWorld(const GameWorld&) = delete;
    GameWorld& operator=(const GameWorld&) = delete;

    /// Advances the world by one fixed step, then applies damage and removes what broke or came to rest.
    void step();

    double time() const { return m_time; }
    double dt() const { return m_settings.dtS; }
    const WorldSettings& settings() const { return m_settings; }
    /// Box2D sub-steps taken by the last step (see WorldSettings::maxSubsteps and maxStackSubsteps).
    int lastSubsteps() const { return m_lastSubsteps; }
    /// Box2D sub-steps a step takes for the level's stacks at the start (WorldSettings::stackDepthPerSubstep).
    int stackSubsteps() const { return m_stackSubsteps; }
    /// The same for the stacks still at rest in the last step: bodies that sleep or move (faster than
    /// kRestingSpeedMps or kRestingSpinRadPerS) are not part of a stack. Never more than stackSubsteps().
    int restingStackSubsteps() const;
    static constexpr double kRestingSpeedMps = 0.2;
    static constexpr double kRestingSpinRadPerS = 0.5;
    /// Sub-steps of a step in which the fastest awake body moves at speedMps: enough to keep every sub-step under
    /// Box2D's translation limit, and at least those the stacks at rest need (restingStackSubsteps()).
    int substepsFor(double speedMps) const;
    /// Fastest a body can move without Box2D capping its speed: 90 % of b2_maxTranslation per sub-step.
    double maxSpeedMps() const;
    /// The most bodies resting on each other at the start (1 for a block on the ground).
    int stackDepth() const { return m_stackDepth; }
    /// Velocity iterations of the settle step (see WorldSettings::settleIterations).
    int settleIterations() const { return m_settleIterations; }
    /// True once the first step, the settle step, has been taken.
    bool settled() const { return m_steps > 0; }
    /// Sub-steps of the settle step done so far, of settleSubstepsPlanned(): a loading screen's progress while the
    /// settle step runs on another thread (the one value safe to read meanwhile).
    int settleSubstepsDone() const { return m_settleSubstepsDone.load(std::memory_order_relaxed); }
    int settleSubstepsPlanned() const { return m_stackSubsteps; }
    /// True when the settle step was not solved but taken from SettleCache (a world of the same bodies and settings
    /// settled before, in this process or, once the game set its directory, in an earlier run).
    bool settleReused() const { return m_settleReused; }

    /// Changes the air and gravity while the world runs (the sandbox's live environment): Box2D's gravity at once,
    /// and the launched bird's flight model from its current state on. Split birds and eggs already in the air keep
    /// the drag they were launched with.
    void setEnvironment(const EnvironmentDef& environment);

    /// The body a bird collides with in this level (its own, or clamped where Box2D would misbehave).
    BirdBody birdBody(const BirdType& bird) const;
    /// Puts a bird at s0 and starts its free flight under the model. Returns its entity index.
    int launchBird(const BirdType& bird, const FlightModel& model, const FlightState& s0);
    /// Takes the launched bird out of the world (split birds and eggs stay until they rest).
    void removeBird();
    /// Takes every bird, split bird and egg out of the world.
    void removeAllBirds();
    /// The launched bird's entity, if it is in the world.
    const Entity* bird() const;
    /// Split birds and eggs still in the world.
    int projectilesInPlay() const { return static_cast<int>(m_projectiles.size()); }
    /// True while the bird has not touched anything since launch.
    bool birdInFreeFlight() const { return m_birdFlight != nullptr; }
    /// Where and when (since launch) the bird first touched something, once it has.
    const std::optional<ContactPoint>& birdContact() const { return m_birdContact; }
    /// What the bird first touched, once it has.
    const std::optional<EntityKind>& birdContactKind() const { return m_birdContactKind; }
    /// The bird's first contact with a block or a pig, once it has had one (not for the ground or terrain).
    const std::optional<FirstImpact>& birdImpact() const { return m_birdImpact; }
    /// The bird's path since launch, one point (t since launch, x, y) per step.
    const std::vector<std::array<double, 3>>& birdPath() const { return m_birdPath; }

    /// Whether the launched bird's ability can be used now: split, boost and egg while it flies free, explode
    /// while it is in the world; each once.
    bool canActivateAbility() const;
    /// Uses the launched bird's ability now (between steps); returns what it did, or nullopt if it cannot.
    std::optional<AbilityUse> activateAbility();

    /// Fraction (0..1) along the straight move a -> b at which a circle of the given radius first touches
    /// level geometry, by Box2D's time of impact: the same query the solver runs for bullets.
    std::optional<double> castCircle(double radiusM, const FlightState& a, const FlightState& b) const;

    /// True when every dynamic body is asleep.
    bool isSettled() const;
    /// The world is calm when no block or pig has moved faster than kCalmSpeedMps or spun faster than
    /// kCalmSpinRadPerS for the last kCalmHoldS (a sleeping body does neither). Birds do not count: they retire on
    /// their own rules. The level starts calm (structures that stand, stand).
    bool isCalm() const;
    static constexpr double kCalmSpeedMps = 0.05;
    static constexpr double kCalmSpinRadPerS = 0.1;
    static constexpr double kCalmHoldS = 0.1;
    /// World time at which the launched bird or one of its split birds first touched anything (a block, a pig, the
    /// ground or terrain); none before that, and none once the shot's bird left the world untouched.
    const std::optional<double>& shotContactTime() const { return m_shotContactTimeS; }
    /// True while the launched bird, a split bird or an egg is in the world.
    bool birdsInPlay() const { return m_birdIndex >= 0 || !m_projectiles.empty(); }
    /// Takes every bird out with a puff (a DestroyedEvent of kind Bird each): the shot is over.
    void retireAllBirds();
    int pigsAlive() const;
    /// True if any body has a non-finite position or velocity.
    bool hasNonFiniteState() const;

    const std::vector<Entity>& entities() const { return m_entities; }
    /// Destroyed things since the last call.
    std::vector<DestroyedEvent> takeDestroyedEvents();
    /// TNT blasts since the last call.
    std::vector<BlastEvent> takeBlastEvents();

    const LevelDef& level() const { return m_level; }
    /// The height of the first static surface (terrain or the ground) straight below (x, fromY): what the slingshot
    /// stands on and its waiting birds queue on. The ground's height when nothing else is below.
    double surfaceBelow(double x, double fromY) const;
    /// The catalog as this level sees it (its material overrides and custom bird applied, see levelCatalog).
    const Catalog& catalog() const { return m_catalog; }
    /// The Box2D world. The first step (the settle step, SettleCache) builds it anew with every body: pointers to
    /// bodies, fixtures or contacts taken before it are not valid after it; take them from entities() again.
    b2World& box2d() { return *m_world; }
    const b2World& box2d() const { return *m_world; }

    class ContactRecorder;

private:
    /// A split bird or an egg: flown by Box2D with the flight model's drag, retired when it rests.
    struct Projectile
    {
        int index = -1;
        double launchTimeS = 0.0; ///< when it was made (world time)
        double shotStartS = 0.0;  ///< when its shot was launched: the flight model's time origin (gusts)
        double slowSinceS = -1.0;
        double groundSinceS = -1.0;              ///< when it first touched the ground or terrain
        bool touched = false;                    ///< it has touched something
        std::unique_ptr<FlightIntegrator> model; ///< evaluates drag and wind for it
    };

    /// A new Box2D world holding the level's bodies as designed (also what a settled state is restored onto).
    void buildWorld();
    void buildLevel();
    void measureStackDepth();
    /// The settle step through SettleCache (see WorldSettings::settleCache); false when this world cannot use it.
    bool settleThroughCache();
    std::uint64_t settleKey() const;
    /// The state the settle step left.
    std::shared_ptr<const SettledState> captureSettled() const;
    /// Rebuilds the world and puts it in the settled state: bodies, velocities, contact manifolds; every body
    /// awake. False (and nothing changed) when the state does not fit this world.
    bool restoreSettled(const SettledState& state);
    void stepBox2d(bool settle);
    /// The most bodies resting on each other (only awake, unmoving ones with restingOnly), counted up to cap.
    int deepestStack(bool restingOnly, int cap) const;
    int stackSubstepsFor(int depth) const;
    int addEntity(Entity entity);
    b2Body* createBirdBody(int index, double radiusM, double massKg, double friction, double restitution,
                           const FlightState& s);
    int substepCount() const;
    void driveBirdFlight();
    void applyFlightForces(b2Body* body, const FlightIntegrator& model, double sinceLaunchS);
    void finishBirdStep(const std::array<double, 2>& stepStart);
    void retireBirds();
    void snapshotImpactVelocities();
    void recordFirstImpact(int otherIndex, double tS);
    /// Completes the first impact's record after damage: whether the body broke, the bird's velocity after it.
    void finishImpactStep();
    void removeProjectile(std::size_t slot);
    void applyDamage();
    /// Break-through: a body that breaks absorbs only its remaining strength; every surviving body that struck it
    /// gets back the rest of the contact impulse along the contact normal.
    void refundBreakingContacts(const std::vector<double>& keptShare);
    DefeatCause causeOf(int index) const;
    void damageEntity(int index, double impulseNs, const DefeatCause& cause);
    /// Radial blast at (x, y): impulse impulseNs (1 - d / R) on every block and pig whose centre is within R, taken
    /// as damage too; appends each push to impulses when given.
    void blast(double x, double y, double radiusM, double impulseNs, std::vector<AbilityImpulse>* impulses, double tS);
    void explodeCrates();
    void removeOutOfBounds();
    void destroyEntity(int index, bool scored, const DefeatCause& cause);
    void updateCalm();
    /// Tracks what a bird touches: first contact, ground contact. Returns true once it touched anything.
    bool noteBirdContacts(const b2Body* body, bool& touched, double& groundSinceS);
    void puff(int index);
    FlightState birdState() const;
    void setBirdVelocity(double vx, double vy);
    int addProjectile(const std::string& typeName, double radiusM, double massKg, const FlightState& s,
                      const FlightModel& model);
    void split(AbilityUse& use);
    void boost(AbilityUse& use);
    void explode(AbilityUse& use);
    void dropEgg(AbilityUse& use);

    LevelDef m_level;
    Catalog m_catalog;
    WorldSettings m_settings;
    std::unique_ptr<b2World> m_world;
    std::unique_ptr<ContactRecorder> m_contacts;
    std::vector<Entity> m_entities;
    std::vector<DestroyedEvent> m_destroyed;
    std::vector<BlastEvent> m_blasts;
    std::vector<int> m_cratesToExplode; ///< TNT crates that broke in this step, blasting after damage
    double m_time = 0.0;
    double m_calmSinceS = 0.0; ///< < 0 while something moves
    std::optional<double> m_shotContactTimeS;
    double m_birdGroundSinceS = -1.0;
    bool m_birdTouched = false;
    long m_steps = 0;
    int m_stackDepth = 0;
    int m_settleIterations = 0;
    std::atomic<int> m_settleSubstepsDone{0};
    int m_lastSubsteps = 1;
    int m_stackSubsteps = 1;
    bool m_settleReused = false;
    int m_restingStackSubsteps = 1;   ///< restingStackSubsteps() at the start of the current step
    double m_lightestBodyKg = 0.0;    ///< lightest block or pig at the start; 0 when there is none
    std::array<double, 3> m_extent{}; ///< left, right, bottom: beyond these a body has left the world
    /// deepestStack's breadth-first search, kept between steps so that a step allocates nothing for it.
    mutable std::vector<int> m_stackDepthOf;
    mutable std::vector<int> m_stackFrontier;
    mutable std::vector<int> m_stackNext;

    int m_birdIndex = -1;
    BirdType m_birdType;
    double m_birdLaunchTime = 0.0;
    double m_birdSlowSinceS = -1.0;
    bool m_abilityUsed = false;
    std::unique_ptr<FlightIntegrator> m_birdFlight; ///< drives the bird until its first contact, then null
    std::unique_ptr<FlightIntegrator> m_birdModel;  ///< the same model, evaluated for drag after contact
    FlightState m_birdStepStart{};
    std::optional<ContactPoint> m_birdContact;
    std::optional<EntityKind> m_birdContactKind;
    std::vector<std::array<double, 3>> m_birdPath;
    std::vector<BodyVelocity> m_stepStartVelocities; ///< per entity, at the start of a step in free flight
    std::optional<FirstImpact> m_birdImpact;
    int m_impactEntity = -1; ///< the body of a first impact recorded in this step, until finishImpactStep
    std::array<double, 2> m_impactRefund{}; ///< impulse the first impact's body gave back by breaking (N s)
    std::vector<Projectile> m_projectiles;
};

} // namespace abalike
