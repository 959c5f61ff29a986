#include "world/abilities/AbilityParams.hpp"

#include <abalike/world/Ability.hpp>
#include <abalike/world/Catalog.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <stdexcept>

namespace abalike
{

namespace
{

/// Two more birds of the same kind leave the bird at +-angle from its velocity, at its speed.
class Split final : public Ability
{
public:
    explicit Split(const nlohmann::json& params) : m_angleDeg(abilityNumber(params, "angle_deg", 10.0, "split")) {}

    std::string_view name() const override { return "split"; }
    AbilityWindow window() const override { return AbilityWindow::FreeFlight; }

    void use(AbilityWorld& world, AbilityUse& use) const override
    {
        // The launched bird flies on unchanged, so its first contact still tests the prediction. (Momentum is not
        // conserved: the new birds come from nowhere, as in the game people know; their momentum is recorded as
        // the ability's impulse.)
        const FlightState s = world.birdState();
        const BirdType& bird = world.birdType();
        const double angle = m_angleDeg * std::numbers::pi / 180.0;
        for (const double sign : {1.0, -1.0})
        {
            const double c = std::cos(sign * angle);
            const double d = std::sin(sign * angle);
            const FlightState fragment{{s.position.x, s.position.y},
                                       {c * s.velocity.x - d * s.velocity.y, d * s.velocity.x + c * s.velocity.y}};
            world.addProjectile({bird.name, bird.radiusM, bird.massKg, fragment, world.birdModel(), true});
            use.impulses.push_back({use.tS, s.position.x, s.position.y, bird.massKg * fragment.velocity.x,
                                    bird.massKg * fragment.velocity.y, "split bird"});
        }
    }

    double number(std::string_view key) const override
    {
        if (key == "angle_deg")
            return m_angleDeg;
        throw std::out_of_range("split has no number \"" + std::string(key) + "\"");
    }
    std::string parameters() const override { return fixedDecimals(m_angleDeg, 1) + " deg"; }
    std::string_view description() const override
    {
        return "two more birds of the same kind at +-angle from the velocity, same speed; the bird flies on";
    }

private:
    double m_angleDeg;
};

} // namespace

std::shared_ptr<const Ability> makeSplit(const nlohmann::json& params)
{
    return std::make_shared<Split>(params);
}

} // namespace abalike
