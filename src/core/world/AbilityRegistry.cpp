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

const std::map<std::string, AbilityFactory, std::less<>>& registry()
{
    static const std::map<std::string, AbilityFactory, std::less<>> abilities = []
    {
        std::map<std::string, AbilityFactory, std::less<>> byName;
        for (const AbilityTableEntry& entry : abilityTable())
            if (entry.name == kNoAbility || !byName.emplace(std::string(entry.name), entry.make).second)
                throw std::logic_error("ability \"" + std::string(entry.name) + "\" is in the table twice");
        return byName;
    }();
    return abilities;
}

} // namespace

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
