#include "world/ContactRecorder.hpp"

#include <abalike/world/GameWorld.hpp>
#include <cmath>
#include <numbers>

namespace abalike
{

namespace
{

/// Drag coefficient of an egg (roughly a sphere).
constexpr double kEggDragCoefficient = 0.47;

} // namespace

bool GameWorld::canActivateAbility() const
{
    if (m_birdIndex < 0 || m_abilityUsed)
        return false;
    const std::string& ability = m_birdType.ability;
    if (ability == "explode")
        return true;
    return birdInFreeFlight() && (ability == "split" || ability == "boost" || ability == "egg");
}

std::optional<AbilityUse> GameWorld::activateAbility()
{
    if (!canActivateAbility())
        return std::nullopt;
    m_abilityUsed = true;
    const FlightState s = birdState();
    AbilityUse use;
    use.ability = m_birdType.ability;
    use.tS = m_time - m_birdLaunchTime;
    use.x = s[0];
    use.y = s[1];
    use.beforeContact = birdInFreeFlight();
    if (use.ability == "split")
        split(use);
    else if (use.ability == "boost")
        boost(use);
    else if (use.ability == "explode")
        explode(use);
    else if (use.ability == "egg")
        dropEgg(use);
    return use;
}

void GameWorld::split(AbilityUse& use)
{
    // Two more birds of the same kind at +-angle from the velocity, at the same speed. The launched bird flies on
    // unchanged, so its first contact still tests the prediction. (Momentum is not conserved: the new birds
    // come from nowhere, as in the game people know; their momentum is recorded as the ability's impulse.)
    const FlightState s = birdState();
    const double angle = m_catalog.abilities().splitAngleDeg * std::numbers::pi / 180.0;
    for (const double sign : {1.0, -1.0})
    {
        const double c = std::cos(sign * angle);
        const double d = std::sin(sign * angle);
        const FlightState fragment{s[0], s[1], c * s[2] - d * s[3], d * s[2] + c * s[3]};
        addProjectile(m_birdType.name, m_birdType.radiusM, m_birdType.massKg, fragment, m_birdModel->model());
        use.impulses.push_back(
            {use.tS, s[0], s[1], m_birdType.massKg * fragment[2], m_birdType.massKg * fragment[3], "split bird"});
    }
}

void GameWorld::boost(AbilityUse& use)
{
    // An impulse m * dv along the current velocity.
    const FlightState s = birdState();
    const double speed = std::hypot(s[2], s[3]);
    const double ux = speed > 1e-9 ? s[2] / speed : 1.0;
    const double uy = speed > 1e-9 ? s[3] / speed : 0.0;
    const double gain = m_catalog.abilities().boostSpeedGainMps;
    setBirdVelocity(s[2] + gain * ux, s[3] + gain * uy);
    use.changedFlight = use.beforeContact;
    use.impulses.push_back({use.tS, s[0], s[1], m_birdType.massKg * gain * ux, m_birdType.massKg * gain * uy, "bird"});
}

void GameWorld::explode(AbilityUse& use)
{
    const AbilityParams& params = m_catalog.abilities();
    blast(use.x, use.y, params.explodeRadiusM, params.explodeImpulseNs, &use.impulses, use.tS);
    explodeCrates();
    use.changedFlight = use.beforeContact;
    removeBird(); // the bird is gone with the blast
}

void GameWorld::dropEgg(AbilityUse& use)
{
    // The egg leaves downwards push_speed faster than the bird; the bird gets the equal and opposite impulse.
    const AbilityParams& params = m_catalog.abilities();
    const FlightState s = birdState();
    const double push = params.eggMassKg * params.eggPushSpeedMps;
    const FlightState egg{s[0], s[1] - (m_birdType.radiusM + params.eggRadiusM), s[2], s[3] - params.eggPushSpeedMps};
    FlightModel eggModel = m_birdModel->model();
    eggModel.massKg = params.eggMassKg;
    eggModel.quadraticDrag =
        quadraticDragCoefficient(m_level.environment.airDensity, kEggDragCoefficient, params.eggRadiusM);
    eggModel.linearDrag *= params.eggRadiusM / m_birdType.radiusM; // Stokes drag grows with the radius
    addProjectile("egg", params.eggRadiusM, params.eggMassKg, egg, eggModel);
    setBirdVelocity(s[2], s[3] + push / m_birdType.massKg);
    use.changedFlight = use.beforeContact;
    use.impulses.push_back({use.tS, egg[0], egg[1], 0.0, -push, "egg"});
    use.impulses.push_back({use.tS, s[0], s[1], 0.0, push, "bird"});
}

} // namespace abalike
