// The table of abilities' looks: every look is keyed by an ability the catalog has (a misspelt key would never be
// used, silently), and once.
#include "render/AbilityLook.hpp"

#include <abalike/world/Catalog.hpp>
#include <gtest/gtest.h>
#include <set>
#include <string>

namespace abalike::app
{
namespace
{

TEST(AbilityLookTable, EveryLookBelongsToAnAbilityOfTheCatalogOnce)
{
    ASSERT_FALSE(abilityLookTable().empty());
    std::set<std::string_view> seen;
    for (const AbilityLookTableEntry& entry : abilityLookTable())
    {
        EXPECT_NE(Catalog::builtin().findAbility(entry.ability), nullptr)
            << "AbilityLookTable.cpp names \"" << entry.ability << "\", which assets/catalog.json has no ability of";
        EXPECT_TRUE(seen.insert(entry.ability).second) << entry.ability << " has two looks";
        EXPECT_TRUE(hasAbilityLook(entry.ability));
    }
}

} // namespace
} // namespace abalike::app
