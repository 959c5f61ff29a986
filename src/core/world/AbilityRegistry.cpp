#include "world/abilities/AbilityParams.hpp"

#include <abalike/world/Ability.hpp>
#include <algorithm>
#include <iomanip>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace abalike
{

namespace
{

std::map<std::string, AbilityFactory, std::less<>>& registry()
{
    // A function-local static: abilities register from their own files' static initialisers, in any order.
    static std::map<std::string, AbilityFactory, std::less<>> abilities;
    return abilities;
}

} // namespace

void AbilityRegistry::add(std::string name, AbilityFactory factory)
{
    if (name == kNoAbility || !registry().emplace(name, std::move(factory)).second)
        throw std::logic_error("ability \"" + name + "\" registered twice");
}

const AbilityFactory* AbilityRegistry::find(std::string_view name)
{
    const auto it = registry().find(name);
    return it == registry().end() ? nullptr : &it->second;
}

std::vector<std::string> AbilityRegistry::names()
{
    std::vector<std::string> names;
    for (const auto& entry : registry())
        names.push_back(entry.first);
    return names;
}

AbilityRegistrar::AbilityRegistrar(std::string name, AbilityFactory factory)
{
    AbilityRegistry::add(std::move(name), std::move(factory));
}

double abilityNumber(const nlohmann::json& params, const char* key, double fallback, std::string_view ability)
{
    if (!params.contains(key))
        return fallback;
    const double value = params.at(key).get<double>();
    if (!(value > 0.0))
        throw std::runtime_error("abilities." + std::string(ability) + "." + key + " must be > 0");
    return value;
}

std::string fixedDecimals(double value, int decimals)
{
    std::ostringstream out;
    out << std::fixed << std::setprecision(decimals) << value;
    return out.str();
}

} // namespace abalike
