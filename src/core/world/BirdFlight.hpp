#pragma once

#include <abalike/flight/FlightIntegrator.hpp>
#include <abalike/flight/Prediction.hpp>
#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Ability.hpp>
#include <abalike/world/BirdBody.hpp>
#include <abalike/world/Catalog.hpp>
#include <array>
#include <memory>
#include <optional>
#include <vector>

class b2Body;

namespace abalike
{

class ImpactRecorder;
class WorldBodies;

/// The shot's birds in the world: the launched bird, flown by the flight model's RK4 until its first contact and by
/// Box2D after it, the split birds and eggs its ability adds, and when each leaves the world.
class BirdFlight
{
public:
    BirdFlight(WorldBodies& bodies, ImpactRecorder& impacts) : m_bodies(bodies), m_impacts(impacts) {}

    /// The body a bird collides with in this level (its own, or clamped where Box2D would misbehave).
    BirdBody birdBody(const BirdType& bird) const;
    /// Puts a bird at s0 and starts its free flight under the model. Returns its entity index.
    int launch(const BirdType& bird, const FlightModel& model, const FlightState& s0);
    /// The launched bird's flight model follows a new environment from its current state on.
    void setEnvironment(const EnvironmentDef& environment);
    void removeBird();
    void removeAllBirds();
    /// Takes out the split bird or egg of this entity, if it is one.
    void removeProjectileOf(int index);
    /// Takes every bird out with a puff: the shot is over.
    void retireAll();

    /// Before a Box2D step: the bird's velocity aimed at its next RK4 state (or the model's forces after contact),
    /// drag and wind on the split birds and eggs. Returns where the bird was.
    Vec2 beforeStep();
    /// After a Box2D step: the bird's first contact (and first impact), its path.
    void afterStep(const Vec2& birdStart);
    /// After a step: what the birds began to touch, and which of them rest, lay on the ground long enough or
    /// outlived their time (birdDone()).
    void updateRest();
    /// The launched bird is done (updateRest): retire() takes it out with a puff unless something (a fuse) acts first.
    bool birdDone() const { return m_birdDone; }
    /// The birds updateRest() found done leave with a puff.
    void retire();

    int birdIndex() const { return m_birdIndex; }
    const BirdType& birdType() const { return m_birdType; }
    double launchTime() const { return m_launchTimeS; }
    bool inFreeFlight() const { return m_flight != nullptr; }
    bool inPlay() const { return m_birdIndex >= 0 || !m_projectiles.empty(); }
    int projectilesInPlay() const { return static_cast<int>(m_projectiles.size()); }
    const std::optional<ContactPoint>& contact() const { return m_contact; }
    const std::optional<EntityKind>& contactKind() const { return m_contactKind; }
    const std::vector<TrackPoint>& path() const { return m_path; }
    /// Beside each point of path(): what the bird touched in the step that ended there (at the contact point: what
    /// it first touched).
    const std::vector<std::vector<BodyRef>>& pathTouches() const { return m_pathTouches; }
    const std::optional<double>& shotContactTime() const { return m_shotContactTimeS; }

    /// The launched bird's state now (x, y, vx, vy).
    FlightState state() const;
    /// The flight model the launched bird flies under.
    const FlightModel& model() const { return m_model->model(); }
    void setVelocity(double vx, double vy);
    void addProjectile(const ProjectileSpec& projectile);
    bool abilityUsed() const { return m_abilityUsed; }
    void markAbilityUsed() { m_abilityUsed = true; }

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
        bool done = false;                       ///< rests, lay on the ground long enough or outlived its time
        std::unique_ptr<FlightIntegrator> model; ///< evaluates drag and wind for it
    };

    b2Body* createBody(int index, double radiusM, double massKg, double friction, double restitution,
                       const FlightState& s);
    void applyFlightForces(b2Body* body, const FlightIntegrator& model, double sinceLaunchS);
    void removeProjectile(std::size_t slot);
    std::vector<BodyRef> touchedInStep(b2Body* body) const;

    WorldBodies& m_bodies;
    ImpactRecorder& m_impacts;
    int m_birdIndex = -1;
    BirdType m_birdType;
    double m_launchTimeS = 0.0;
    double m_slowSinceS = -1.0;
    double m_groundSinceS = -1.0;
    bool m_touched = false;
    bool m_abilityUsed = false;
    bool m_birdDone = false; ///< the launched bird rests, lay on the ground long enough or outlived its time
    std::unique_ptr<FlightIntegrator> m_flight; ///< drives the bird until its first contact, then null
    std::unique_ptr<FlightIntegrator> m_model;  ///< the same model, evaluated for drag after contact
    FlightState m_stepStart{};
    std::optional<ContactPoint> m_contact;
    std::optional<EntityKind> m_contactKind;
    std::vector<TrackPoint> m_path;
    std::vector<std::vector<BodyRef>> m_pathTouches;
    std::optional<double> m_shotContactTimeS;
    std::vector<Projectile> m_projectiles;
};

} // namespace abalike
