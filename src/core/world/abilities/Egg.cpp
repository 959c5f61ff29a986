#include "world/abilities/AbilityParams.hpp"

#include <abalike/world/Ability.hpp>
#include <abalike/world/Catalog.hpp>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace abalike
{

namespace
{

/// Drag coefficient of an egg (roughly a sphere).
constexpr double kEggDragCoefficient = 0.47;

/// The bird lays an egg that leaves downwards push_speed faster than the bird; the bird gets the equal and opposite
/// impulse upwards.
class Egg final : public Ability
{
public:
    explicit Egg(const nlohmann::json& params)
        : m_massKg(abilityNumber(params, "mass_kg", 10.0, "egg")),
          m_radiusM(abilityNumber(params, "radius_m", 0.2, "egg")),
          m_pushSpeedMps(abilityNumber(params, "push_speed_mps", 15.0, "egg"))
    {
    }

    std::string_view name() const override { return "egg"; }
    AbilityWindow window() const override { return AbilityWindow::FreeFlight; }

    void use(AbilityWorld& world, AbilityUse& use) const override
    {
        const FlightState s = world.birdState();
        const BirdType& bird = world.birdType();
        const double push = m_massKg * m_pushSpeedMps;
        ProjectileSpec egg;
        egg.typeName = "egg";
        egg.radiusM = m_radiusM;
        egg.massKg = m_massKg;
        egg.state = {{s.position.x, s.position.y - (bird.radiusM + m_radiusM)},
                     {s.velocity.x, s.velocity.y - m_pushSpeedMps}};
        egg.model = world.birdModel();
        egg.model.massKg = m_massKg;
        egg.model.quadraticDrag = quadraticDragCoefficient(world.airDensity(), kEggDragCoefficient, m_radiusM);
        egg.model.linearDrag *= m_radiusM / bird.radiusM; // Stokes drag grows with the radius
        egg.shotBird = false;
        world.addProjectile(egg);
        world.setBirdVelocity(s.velocity.x, s.velocity.y + push / bird.massKg);
        use.changedFlight = use.beforeContact;
        use.impulses.push_back({use.tS, egg.state.position.x, egg.state.position.y, 0.0, -push, "egg"});
        use.impulses.push_back({use.tS, s.position.x, s.position.y, 0.0, push, "bird"});
    }

    double number(std::string_view key) const override
    {
        if (key == "mass_kg")
            return m_massKg;
        if (key == "radius_m")
            return m_radiusM;
        if (key == "push_speed_mps")
            return m_pushSpeedMps;
        throw std::out_of_range("egg has no number \"" + std::string(key) + "\"");
    }
    std::string parameters() const override
    {
        return fixedDecimals(m_massKg, 1) + " kg, r = " + fixedDecimals(m_radiusM, 2) + " m, " +
               fixedDecimals(m_pushSpeedMps, 1) + " m/s";
    }
    std::optional<DroppedPayload> dropped() const override { return DroppedPayload{m_pushSpeedMps, m_radiusM}; }
    std::string_view description() const override
    {
        return "the egg leaves downwards that much faster than the bird; the bird gets the equal and opposite "
               "impulse upwards";
    }

private:
    double m_massKg;
    double m_radiusM;
    double m_pushSpeedMps;
};

} // namespace

std::shared_ptr<const Ability> makeEgg(const nlohmann::json& params)
{
    return std::make_shared<Egg>(params);
}

} // namespace abalike
