// Linked against the core's archive the plain way, without --whole-archive: the linker keeps only the objects
// something names. Every ability must still be there, because the table of abilities names each one.
#include <abalike/world/Ability.hpp>
#include <abalike/world/Catalog.hpp>
#include <algorithm>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace abalike
{
namespace
{

TEST(PlainLink, EveryAbilityTheCatalogNamesIsThere)
{
    // The built-in catalog throws "unknown ability" when a bird names one the program lacks.
    const Catalog& catalog = Catalog::builtin();
    std::vector<std::string> made;
    for (const auto& ability : catalog.abilities())
        made.emplace_back(ability->name());
    std::sort(made.begin(), made.end());
    EXPECT_EQ(made, AbilityRegistry::names());
    for (const BirdType& bird : catalog.birds())
    {
        if (bird.ability)
        {
            EXPECT_NE(AbilityRegistry::find(bird.ability->name()), nullptr) << bird.name;
        }
    }
    EXPECT_EQ(AbilityRegistry::names().size(), abilityTable().size());
}

} // namespace
} // namespace abalike
