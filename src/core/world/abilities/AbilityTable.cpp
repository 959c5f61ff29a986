#include <abalike/world/Ability.hpp>
#include <nlohmann/json_fwd.hpp>

namespace abalike
{

// Each ability's file defines its maker. The table names every one, so whatever links the core keeps them all
// (Box2D fills its contact table the same way, b2Contact::InitializeRegisters). A new ability adds its maker here.
std::shared_ptr<const Ability> makeBoost(const nlohmann::json& params);
std::shared_ptr<const Ability> makeEgg(const nlohmann::json& params);
std::shared_ptr<const Ability> makeExplode(const nlohmann::json& params);
std::shared_ptr<const Ability> makeSplit(const nlohmann::json& params);

const std::vector<AbilityTableEntry>& abilityTable()
{
    static const std::vector<AbilityTableEntry> table{
        {"boost", makeBoost},
        {"egg", makeEgg},
        {"explode", makeExplode},
        {"split", makeSplit},
    };
    return table;
}

} // namespace abalike
