#include "world/abilities/AbilityParams.hpp"

#include <abalike/world/Ability.hpp>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace abalike
{

namespace
{

/// The bird blows up: a radial impulse J (1 - d / R) on every block and pig within R, taken as damage too.
class Explode final : public Ability
{
public:
    explicit Explode(const nlohmann::json& params)
        : m_radiusM(abilityNumber(params, "radius_m", 3.0, "explode")),
          m_impulseNs(abilityNumber(params, "impulse_ns", 250.0, "explode")),
          m_fuseS(abilityNumber(params, "fuse_s", 0.0, "explode"))
    {
    }

    std::string_view name() const override { return "explode"; }
    AbilityWindow window() const override { return AbilityWindow::InWorld; }

    void use(AbilityWorld& world, AbilityUse& use) const override
    {
        world.blast(use.x, use.y, m_radiusM, m_impulseNs, use.impulses, use.tS);
        use.changedFlight = use.beforeContact;
        use.reachM = m_radiusM;
        world.removeBird(); // the bird is gone with the blast
    }

    double number(std::string_view key) const override
    {
        if (key == "radius_m")
            return m_radiusM;
        if (key == "impulse_ns")
            return m_impulseNs;
        if (key == "fuse_s")
            return m_fuseS;
        throw std::out_of_range("explode has no number \"" + std::string(key) + "\"");
    }
    std::string parameters() const override
    {
        return "R = " + fixedDecimals(m_radiusM, 1) + " m, J = " + fixedDecimals(m_impulseNs, 0) + " N s" +
               (m_fuseS > 0.0 ? ", fuse " + fixedDecimals(m_fuseS, 1) + " s" : "");
    }
    std::optional<double> fuseS() const override
    {
        return m_fuseS > 0.0 ? std::optional<double>(m_fuseS) : std::nullopt;
    }
    std::string_view description() const override
    {
        return "radial impulse J (1 - d/R) on every block and pig within R, absorbed as damage too; the bird is gone "
               "(untapped, it goes off by itself a fuse's time after its first contact, or as it comes to rest)";
    }

private:
    double m_radiusM;
    double m_impulseNs;
    double m_fuseS; ///< 0: no fuse, it waits for the player
};

} // namespace

std::shared_ptr<const Ability> makeExplode(const nlohmann::json& params)
{
    return std::make_shared<Explode>(params);
}

} // namespace abalike
