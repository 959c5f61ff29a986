#include <abalike/design/Solver.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/level/LevelText.hpp>
#include <abalike/world/RestFindings.hpp>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

LevelDef scene(const std::string& blocksAndPigs)
{
    return parseLevel(R"({"format": 1, "id": "t", "title": "rest", "ground": {"y": 0.0},
        "slingshot": {"x": 0.0, "y": 1.5}, "birds": ["red"], )" +
                          blocksAndPigs + R"(, "stars": [1, 2, 3]})",
                      "rest.json", Catalog::builtin());
}

std::vector<RestFinding> findingsOf(const LevelDef& level)
{
    return restFindings(level, Catalog::builtin(), checkRest(level));
}

TEST(RestFindings, APigOneCentimetreAboveTheGroundFloatsAndGetsItsY)
{
    const auto findings = findingsOf(scene(R"("blocks": [], "pigs": [{"type": "small", "x": 20.0, "y": 0.26}])"));
    ASSERT_EQ(findings.size(), 1u);
    EXPECT_EQ(findings[0].pointer, "/pigs/0");
    EXPECT_EQ(findings[0].what, "floats 1.0 cm above the ground");
    EXPECT_EQ(findings[0].fix, "set y = 0.25");
    ASSERT_TRUE(findings[0].snapY);
    EXPECT_NEAR(*findings[0].snapY, 0.25, 1e-12);
}

TEST(RestFindings, APlankOverlappingItsPostNamesThePostAndTheDepth)
{
    const auto findings = findingsOf(scene(R"("blocks": [
        {"material": "wood", "x": 20.0, "y": 0.75, "w": 0.25, "h": 1.5},
        {"material": "wood", "x": 22.0, "y": 0.75, "w": 0.25, "h": 1.5},
        {"material": "wood", "x": 21.0, "y": 1.618, "w": 2.6, "h": 0.25}],
        "pigs": [{"type": "small", "x": 30.0, "y": 0.25}])"));
    ASSERT_FALSE(findings.empty());
    EXPECT_EQ(findings.back().pointer, "/blocks/2");
    EXPECT_EQ(findings.back().what, "overlaps block 0 (wood) by 7.0 mm");
    EXPECT_EQ(findings.back().fix, "set y = 1.625");
}

TEST(RestFindings, ACantileverFallsPastItsSupportsEdge)
{
    const auto findings = findingsOf(scene(R"("blocks": [
        {"material": "wood", "x": 40.0, "y": 0.25, "w": 1.0, "h": 0.5},
        {"material": "stone", "x": 40.9, "y": 0.75, "w": 1.0, "h": 0.5}],
        "pigs": [{"type": "small", "x": 30.0, "y": 0.25}])"));
    ASSERT_FALSE(findings.empty());
    const RestFinding& f = findings.back();
    EXPECT_EQ(f.pointer, "/blocks/1");
    EXPECT_EQ(f.what.rfind("falls: its centre of mass is 40.0 cm past block 0 (wood)'s edge", 0), 0u) << f.what;
    EXPECT_EQ(f.fix, "move it 40.0 cm left or support its centre");
    EXPECT_FALSE(f.snapY);
}

TEST(RestFindings, ABlockFloatingFarAboveItsSupportGetsAFixButNoSnap)
{
    const auto findings = findingsOf(scene(R"("blocks": [{"material": "wood", "x": 20.0, "y": 0.6, "w": 1.0, "h": 1.0}],
        "pigs": [{"type": "small", "x": 30.0, "y": 0.25}])"));
    ASSERT_EQ(findings.size(), 1u);
    EXPECT_EQ(findings[0].what.rfind("floats 10.0 cm above the ground", 0), 0u) << findings[0].what;
    EXPECT_EQ(findings[0].fix, "set y = 0.5");
    EXPECT_FALSE(findings[0].snapY) << "more than 2 cm is a design decision, not a slip";
}

TEST(RestFindings, AStandingLevelHasNone)
{
    const LevelDef level =
        loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/1-1-first-flight.json", Catalog::builtin());
    EXPECT_TRUE(findingsOf(level).empty());
}

TEST(LevelText, ReplaceNumberKeepsEveryOtherByte)
{
    const std::string text = "{\n  \"pigs\": [ { \"type\": \"small\",  \"x\": 21.0, \"y\": 0.26 } ]\n}\n";
    EXPECT_EQ(replaceNumber(text, "/pigs/0/y", "0.25"),
              "{\n  \"pigs\": [ { \"type\": \"small\",  \"x\": 21.0, \"y\": 0.25 } ]\n}\n");
    EXPECT_THROW(replaceNumber(text, "/pigs/0/type", "1"), std::invalid_argument);
    EXPECT_THROW(replaceNumber(text, "/pigs/3/y", "1"), std::invalid_argument);
}

TEST(Solver, APigThatFallsBeforeAnyShotIsNeverCountedAsAWin)
{
    // A small pig on a plank whose only post stands off-centre: it falls 2 m and dies with no shot fired.
    const LevelDef level = scene(R"("blocks": [
        {"material": "wood", "x": 20.0, "y": 1.0, "w": 0.25, "h": 2.0},
        {"material": "wood", "x": 21.2, "y": 2.125, "w": 2.6, "h": 0.25}],
        "pigs": [{"type": "small", "x": 22.2, "y": 2.5}])");
    const Solution solution = solveLevel(level);
    EXPECT_FALSE(solution.outcome.won);
    EXPECT_EQ(solution.pigsFallingAlone, std::vector<int>{0});
    EXPECT_EQ(solution.simulations, 0u);
}

} // namespace
} // namespace abalike
