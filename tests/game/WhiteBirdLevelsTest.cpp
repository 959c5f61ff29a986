#include "../SanitizerBuild.hpp"

#include <abalike/design/Solver.hpp>
#include <abalike/level/LevelIO.hpp>

#include <gtest/gtest.h>
#include <string>

namespace abalike
{
namespace
{

class WhiteBirdLevels : public testing::TestWithParam<const char*>
{
protected:
    LevelDef level() const
    {
        return loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/" + GetParam() + ".json", Catalog::builtin());
    }
};

// Each level hides its large pig in a cellar under a stone hatch that a bird alone cannot break in one blow: the
// white bird's egg, dropped over it, is the tool. The solver finds the drop (it times a payload over each standing
// pig) and wins; without abilities it cannot.
TEST_P(WhiteBirdLevels, TheEggIsTheSolversToolAndNothingElseWins)
{
    if (test::kSanitizerBuild)
        GTEST_SKIP() << "two full solves take 40 s a level under the sanitizers; the Release stage runs them";
    const LevelDef cellar = level();
    const Solution withEgg = solveLevel(cellar, Catalog::builtin(), {});
    ASSERT_TRUE(withEgg.outcome.won) << GetParam();
    bool dropped = false;
    for (std::size_t i = 0; i < withEgg.shots.size(); ++i)
        dropped = dropped || (cellar.birds[i] == "white" && withEgg.shots[i].abilityAtS.has_value());
    EXPECT_TRUE(dropped) << GetParam() << ": the winning sequence does not drop the egg";

    SolverOptions noAbilities;
    noAbilities.tryAbilities = false;
    const Solution without = solveLevel(cellar, Catalog::builtin(), noAbilities);
    EXPECT_FALSE(without.outcome.won) << GetParam();
    EXPECT_GE(without.outcome.pigsRemaining, 1) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Campaign, WhiteBirdLevels,
                         testing::Values("1-8-from-the-cliff", "4-7-hard-hats", "4-8-cold-feet"));

} // namespace
} // namespace abalike
