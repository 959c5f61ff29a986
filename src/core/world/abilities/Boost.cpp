#include "world/abilities/AbilityParams.hpp"

#include <abalike/world/Ability.hpp>
#include <abalike/world/Catalog.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace abalike
{

namespace
{

/// An impulse m dv along the bird's current velocity.
class Boost final : public Ability
{
public:
    explicit Boost(const nlohmann::json& params)
        : m_speedGainMps(abilityNumber(params, "speed_gain_mps", 15.0, "boost"))
    {
    }

    std::string_view name() const override { return "boost"; }
    AbilityWindow window() const override { return AbilityWindow::FreeFlight; }

    void use(AbilityWorld& world, AbilityUse& use) const override
    {
        const FlightState s = world.birdState();
        const double mass = world.birdType().massKg;
        const double speed = std::hypot(s.velocity.x, s.velocity.y);
        const double ux = speed > 1e-9 ? s.velocity.x / speed : 1.0;
        const double uy = speed > 1e-9 ? s.velocity.y / speed : 0.0;
        const double gain = m_speedGainMps;
        world.setBirdVelocity(s.velocity.x + gain * ux, s.velocity.y + gain * uy);
        use.changedFlight = use.beforeContact;
        use.impulses.push_back({use.tS, s.position.x, s.position.y, mass * gain * ux, mass * gain * uy, "bird"});
    }

    double number(std::string_view key) const override
    {
        if (key == "speed_gain_mps")
            return m_speedGainMps;
        throw std::out_of_range("boost has no number \"" + std::string(key) + "\"");
    }
    std::string parameters() const override
    {
        // append, not "+" + ...: GCC 12 warns falsely (-Wrestrict) on operator+ with a temporary.
        std::string text = "+";
        return text.append(fixedDecimals(m_speedGainMps, 1)).append(" m/s");
    }
    std::string_view description() const override { return "impulse m dv along the current velocity"; }

private:
    double m_speedGainMps;
};

} // namespace

std::shared_ptr<const Ability> makeBoost(const nlohmann::json& params)
{
    return std::make_shared<Boost>(params);
}

} // namespace abalike
