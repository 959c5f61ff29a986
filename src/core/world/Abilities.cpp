#include "world/BirdFlight.hpp"
#include "world/Damage.hpp"
#include "world/WorldBodies.hpp"

#include <abalike/world/GameWorld.hpp>
#include <utility>

namespace abalike
{

namespace
{

/// What an ability may do, on the launched bird (BirdFlight) and with blasts (Damage).
class AbilityContext final : public AbilityWorld
{
public:
    AbilityContext(BirdFlight& birds, Damage& damage, const WorldBodies& bodies)
        : m_birds(birds), m_damage(damage), m_bodies(bodies)
    {
    }

    FlightState birdState() const override { return m_birds.state(); }
    const BirdType& birdType() const override { return m_birds.birdType(); }
    const FlightModel& birdModel() const override { return m_birds.model(); }
    double airDensity() const override { return m_bodies.level().environment.airDensity; }
    void setBirdVelocity(double vx, double vy) override { m_birds.setVelocity(vx, vy); }
    void addProjectile(const ProjectileSpec& projectile) override { m_birds.addProjectile(projectile); }
    void blast(double x, double y, double radiusM, double impulseNs, std::vector<AbilityImpulse>& impulses,
               double tS) override
    {
        m_damage.blast(x, y, radiusM, impulseNs, &impulses, tS);
        m_damage.explodeCrates();
    }
    void removeBird() override { m_birds.removeBird(); }

private:
    BirdFlight& m_birds;
    Damage& m_damage;
    const WorldBodies& m_bodies;
};

} // namespace

bool GameWorld::canActivateAbility() const
{
    const Ability* ability = m_birds->birdType().ability.get();
    if (m_birds->birdIndex() < 0 || m_birds->abilityUsed() || ability == nullptr)
        return false;
    switch (ability->window())
    {
    case AbilityWindow::InWorld:
        return true;
    case AbilityWindow::FreeFlight:
        return m_birds->inFreeFlight();
    }
    return false;
}

std::optional<AbilityUse> GameWorld::activateAbility()
{
    if (!canActivateAbility())
        return std::nullopt;
    m_birds->markAbilityUsed();
    const FlightState s = m_birds->state();
    const Ability& ability = *m_birds->birdType().ability;
    AbilityUse use;
    use.ability = std::string(ability.name());
    use.tS = m_bodies->time() - m_birds->launchTime();
    use.x = s.position.x;
    use.y = s.position.y;
    use.beforeContact = m_birds->inFreeFlight();
    AbilityContext context(*m_birds, *m_damage, *m_bodies);
    ability.use(context, use);
    return use;
}

void GameWorld::fuseAbility()
{
    // An ability with a fuse the player never used goes off by itself: the fuse's time after the bird's first contact,
    // or as the bird comes to rest (or would otherwise leave), whichever is first.
    const Ability* ability = m_birds->birdType().ability.get();
    if (ability == nullptr || !ability->fuseS() || !canActivateAbility())
        return;
    const std::optional<double>& contact = m_birds->shotContactTime();
    const bool burnt = contact && m_bodies->time() - *contact >= *ability->fuseS() - 1e-9;
    if (!burnt && !m_birds->birdDone())
        return;
    m_fused = activateAbility();
    if (m_fused)
        m_fused->byFuse = true;
}

std::optional<AbilityUse> GameWorld::takeFusedAbility()
{
    return std::exchange(m_fused, std::nullopt);
}

} // namespace abalike
