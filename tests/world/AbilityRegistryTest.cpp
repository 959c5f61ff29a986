#include "CatalogLoadError.hpp"

#include <abalike/world/Ability.hpp>
#include <abalike/world/Catalog.hpp>
#include <algorithm>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

namespace abalike
{
namespace
{

std::string catalogText()
{
    std::ifstream in(std::string(ABALIKE_SOURCE_DIR) + "/assets/catalog.json");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// 1-based line of the first occurrence of needle in text.
int lineOf(const std::string& text, const std::string& needle)
{
    const std::size_t at = text.find(needle);
    return at == std::string::npos ? 0 : 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

TEST(AbilityRegistry, EveryAbilityTheCatalogNamesIsRegisteredAndConfigured)
{
    for (const BirdType& bird : Catalog::builtin().birds())
    {
        if (!bird.ability)
        {
            EXPECT_EQ(bird.abilityName(), "none") << bird.name;
            continue;
        }
        EXPECT_NE(AbilityRegistry::find(bird.ability->name()), nullptr) << bird.name;
        EXPECT_EQ(Catalog::builtin().findAbility(bird.ability->name()), bird.ability.get()) << bird.name;
    }
    // And the other way round: every ability the table knows is configured by the catalog, none is left unused.
    std::vector<std::string> configured;
    for (const auto& ability : Catalog::builtin().abilities())
        configured.emplace_back(ability->name());
    std::sort(configured.begin(), configured.end());
    EXPECT_EQ(configured, AbilityRegistry::names());
    EXPECT_FALSE(configured.empty());
}

TEST(AbilityRegistry, AMisspeltAbilityIsALocatedErrorWithASuggestion)
{
    std::string text = catalogText();
    const std::string blue = R"("ability": "split")";
    const int line = lineOf(text, blue);
    ASSERT_GT(line, 0);
    text.replace(text.find(blue), blue.size(), R"("ability": "spilt")");
    const std::string error = test::catalogLoadError(text);
    EXPECT_NE(error.find("assets/catalog.json:" + std::to_string(line) + ":"), std::string::npos) << error;
    EXPECT_NE(error.find("/birds/1/ability: unknown ability \"spilt\" (did you mean \"split\"?)"), std::string::npos)
        << error;
}

TEST(AbilityRegistry, AnUnknownAbilityFarFromAnyNameListsTheKnownOnes)
{
    // A name longer than every known one by more than any suggestion tolerates, made of a letter none of them has
    // twice in a row: far from every ability there is or will be.
    std::size_t longest = 0;
    for (const std::string& name : AbilityRegistry::names())
        longest = std::max(longest, name.size());
    const std::string far(longest + 8, 'q');
    std::string text = catalogText();
    const std::string red = R"("ability": "none")";
    ASSERT_NE(text.find(red), std::string::npos);
    text.replace(text.find(red), red.size(), R"("ability": ")" + far + "\"");
    std::string expected = "/birds/0/ability: unknown ability \"" + far + "\" (expected one of: none";
    for (const std::string& name : AbilityRegistry::names())
        expected += ", " + name;
    const std::string error = test::catalogLoadError(text);
    EXPECT_NE(error.find(expected + ")"), std::string::npos) << error;
}

TEST(AbilityRegistry, NumbersForAnAbilityNobodyKnowsAreAnErrorToo)
{
    std::string text = catalogText();
    const std::string block = R"("abilities": {)";
    text.replace(text.find(block), block.size(), R"("abilities": { "sonic": { "speed_mps": 3 },)");
    const std::string error = test::catalogLoadError(text);
    EXPECT_NE(error.find("/abilities/sonic: unknown ability \"sonic\""), std::string::npos) << error;
}

TEST(AbilityRegistry, TheNumbersLevelTextsMayNameAreDeclaredWithTheAbility)
{
    // {egg_mass} in a level's hint is the egg's mass_kg because the egg's block says so, not because code names it.
    const auto& values = Catalog::builtin().abilityTextValues();
    ASSERT_FALSE(values.empty());
    for (const AbilityTextValue& value : values)
    {
        const Ability* ability = Catalog::builtin().findAbility(value.ability);
        ASSERT_NE(ability, nullptr) << value.name;
        EXPECT_NO_THROW((void)ability->number(value.number)) << value.name;
    }
    std::string text = catalogText();
    const std::string number = R"("number": "mass_kg")";
    ASSERT_NE(text.find(number), std::string::npos);
    text.replace(text.find(number), number.size(), R"("number": "mass_g")");
    EXPECT_NE(test::catalogLoadError(text).find("/abilities/egg/text_values/egg_mass/number: egg has no number "
                                                "\"mass_g\""),
              std::string::npos)
        << test::catalogLoadError(text);
}

TEST(AbilityRegistry, AnAbilitysNumbersComeFromTheCatalogAndAreChecked)
{
    std::string text = catalogText();
    const std::string angle = R"("angle_deg": 10.0)";
    ASSERT_NE(text.find(angle), std::string::npos);
    text.replace(text.find(angle), angle.size(), R"("angle_deg": 25.0)");
    EXPECT_EQ(Catalog::fromJson(text).findAbility("split")->number("angle_deg"), 25.0);
    text.replace(text.find(R"("angle_deg": 25.0)"), angle.size(), R"("angle_deg": -1.0)");
    EXPECT_NE(test::catalogLoadError(text).find("abilities.split.angle_deg must be > 0"), std::string::npos);
    EXPECT_THROW(Catalog::builtin().findAbility("split")->number("nope"), std::out_of_range);
}

} // namespace
} // namespace abalike
