#include "render/AbilityLook.hpp"

namespace abalike::app
{

// Each look's file defines its maker. The table names every one, so whatever links the app keeps them all. An
// ability with a look of its own adds its maker here, by the ability's name in the catalog.
std::unique_ptr<AbilityLook> makeEggLook();
std::unique_ptr<AbilityLook> makeExplodeLook();

const std::vector<AbilityLookTableEntry>& abilityLookTable()
{
    static const std::vector<AbilityLookTableEntry> table{
        {"egg", makeEggLook},
        {"explode", makeExplodeLook},
    };
    return table;
}

} // namespace abalike::app
