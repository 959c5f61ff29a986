#pragma once

#include <abalike/flight/FlightIntegrator.hpp>
#include <abalike/flight/Prediction.hpp>
#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Ability.hpp>
#include <abalike/world/BirdBody.hpp>
#include <abalike/world/Catalog.hpp>
#include <abalike/world/Entity.hpp>
#include <abalike/world/FirstImpact.hpp>
#include <abalike/world/WorldSettings.hpp>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class b2Body;
class b2World;

namespace abalike
{

class BirdFlight;
class Damage;
class ImpactRecorder;
class SettleStep;
class WorldBodies;
class WorldStepper;

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

    double time() const;
    double dt() const;
    const WorldSettings& settings() const;
    /// Box2D sub-steps taken by the last step (see WorldSettings::maxSubsteps and maxStackSubsteps).
    int lastSubsteps() const;
    /// Box2D sub-steps a step takes for the level's stacks at the start (WorldSettings::stackDepthPerSubstep).
    int stackSubsteps() const;
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
    int stackDepth() const;
    /// Velocity iterations of the settle step (see WorldSettings::settleIterations).
    int settleIterations() const;
    /// True once the first step, the settle step, has been taken.
    bool settled() const { return m_steps > 0; }
    /// Sub-steps of the settle step done so far, of settleSubstepsPlanned(): a loading screen's progress while the
    /// settle step runs on another thread (the one value safe to read meanwhile).
    int settleSubstepsDone() const;
    int settleSubstepsPlanned() const;
    /// True when the settle step was not solved but taken from SettleCache (a world of the same bodies and settings
    /// settled before, in this process or, once the game set its directory, in an earlier run).
    bool settleReused() const;

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
    int projectilesInPlay() const;
    /// True while the bird has not touched anything since launch.
    bool birdInFreeFlight() const;
    /// Where and when (since launch) the bird first touched something, once it has.
    const std::optional<ContactPoint>& birdContact() const;
    /// What the bird first touched, once it has.
    const std::optional<EntityKind>& birdContactKind() const;
    /// The bird's first contact with a block or a pig, once it has had one (not for the ground or terrain).
    const std::optional<FirstImpact>& birdImpact() const;
    /// The bird's path since launch, one point (t since launch, x, y) per step.
    const std::vector<TrackPoint>& birdPath() const;
    /// Beside each point of birdPath(): what the bird touched in the step that ended there.
    const std::vector<std::vector<BodyRef>>& birdPathTouches() const;

    /// Whether the launched bird's ability can be used now: split, boost and egg while it flies free, explode
    /// while it is in the world; each once.
    bool canActivateAbility() const;
    /// Uses the launched bird's ability now (between steps); returns what it did, or nullopt if it cannot.
    std::optional<AbilityUse> activateAbility();
    /// What an ability with a fuse (Ability::fuseS) did when it went off by itself in the last step, once; the session
    /// records it as the shot's ability.
    std::optional<AbilityUse> takeFusedAbility();

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
    const std::optional<double>& shotContactTime() const;
    /// True while the launched bird, a split bird or an egg is in the world.
    bool birdsInPlay() const;
    /// Takes every bird out with a puff (a DestroyedEvent of kind Bird each): the shot is over.
    void retireAllBirds();
    int pigsAlive() const;
    /// True if any body has a non-finite position or velocity.
    bool hasNonFiniteState() const;

    const std::vector<Entity>& entities() const;
    /// Destroyed things since the last call.
    std::vector<DestroyedEvent> takeDestroyedEvents();
    /// TNT blasts since the last call.
    std::vector<BlastEvent> takeBlastEvents();

    const LevelDef& level() const;
    /// The height of the first static surface (terrain or the ground) straight below (x, fromY): what the slingshot
    /// stands on and its waiting birds queue on. The ground's height when nothing else is below.
    double surfaceBelow(double x, double fromY) const;
    /// The catalog as this level sees it (its material overrides and custom bird applied, see levelCatalog).
    const Catalog& catalog() const;
    /// The Box2D world. The first step (the settle step, SettleCache) builds it anew with every body: pointers to
    /// bodies, fixtures or contacts taken before it are not valid after it; take them from entities() again.
    b2World& box2d();
    const b2World& box2d() const;

private:
    void removeOutOfBounds();
    /// In a step, after the birds' rest is known: an unused ability whose fuse burnt down goes off.
    void fuseAbility();

    std::unique_ptr<WorldBodies> m_bodies;
    std::unique_ptr<WorldStepper> m_stepper;
    std::unique_ptr<SettleStep> m_settle;
    std::unique_ptr<ImpactRecorder> m_impacts;
    std::unique_ptr<Damage> m_damage;
    std::unique_ptr<BirdFlight> m_birds;
    std::optional<AbilityUse> m_fused; ///< set by fuseAbility(), taken by takeFusedAbility()
    long m_steps = 0;
};

} // namespace abalike
