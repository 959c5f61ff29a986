// Claims: what a level's texts promise, computed for the level (levels/README.md, "Claims").
#include <abalike/level/Campaign.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/teach/Claims.hpp>
#include <filesystem>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

const std::string kLevels = std::string(ABALIKE_SOURCE_DIR) + "/levels/";

TEST(Claims, EveryClaimOfTheCampaignAndTheLessonsHolds)
{
    std::vector<std::string> paths = loadCampaign(kLevels + "campaign.json");
    for (const auto& entry : std::filesystem::directory_iterator(kLevels + "lessons"))
        if (entry.path().extension() == ".json")
            paths.push_back(entry.path().string());
    int claims = 0;
    for (const std::string& path : paths)
    {
        const LevelDef level = loadLevel(path, Catalog::builtin());
        for (std::size_t i = 0; i < level.claims.size(); ++i, ++claims)
        {
            const ClaimResult result = evaluateClaim(level.claims[i], level, Catalog::builtin());
            EXPECT_TRUE(result.holds) << path << " /claims/" << i << ": " << result.message;
        }
    }
    EXPECT_GE(claims, 12) << "the wind, gravity and air levels state comparisons";
}

LevelDef headwind()
{
    return loadLevel(kLevels + "3-5-headwind.json", Catalog::builtin());
}

ClaimDef comparison(const std::string& about, const std::string& holds)
{
    ClaimDef claim;
    claim.about = about;
    claim.holds = holds;
    return claim;
}

TEST(Claims, AHeadwindLowersTheBestAngleAndATailwindRaisesIt)
{
    // The misconception the campaign once taught: "in a headwind, aim higher".
    const LevelDef against = headwind();
    const ClaimResult lower =
        evaluateClaim(comparison("/concept", "best_angle:red < calm_best_angle:red"), against, Catalog::builtin());
    EXPECT_TRUE(lower.holds) << lower.message;
    EXPECT_NEAR(lower.left, 34.0, 0.5);
    EXPECT_NEAR(lower.right, 39.4, 0.5);
    const LevelDef with = loadLevel(kLevels + "3-7-windy-ridge.json", Catalog::builtin());
    const ClaimResult farther =
        evaluateClaim(comparison("/concept", "best_range:red > vacuum_best_range:red"), with, Catalog::builtin());
    EXPECT_FALSE(farther.holds) << "an 8 m/s tailwind does not beat vacuum at full pull";
    EXPECT_EQ(farther.message.rfind("best_range:red = 65.2", 0), 0u) << farther.message;
    EXPECT_NE(farther.message.find(" is not > vacuum_best_range:red = 93.2"), std::string::npos) << farther.message;
}

TEST(Claims, ComparisonsAndExpressions)
{
    const LevelDef level = headwind();
    const auto holds = [&](const std::string& claim)
    {
        return evaluateClaim(comparison("/concept", claim), level, Catalog::builtin()).holds;
    };
    EXPECT_TRUE(holds("v_max:red > v_max:black"));
    EXPECT_TRUE(holds("v_max:red >= 30"));
    EXPECT_TRUE(holds("v_max:red <= 30"));
    EXPECT_FALSE(holds("v_max:red < 30"));
    EXPECT_TRUE(holds("mass:red * v_max:red < mass:black * v_max:black"));
    EXPECT_TRUE(holds("  g>9  "));
}

TEST(Claims, SyntaxIsCheckedWithoutComputing)
{
    const LevelDef level = headwind();
    std::string error;
    EXPECT_FALSE(splitClaim("best_angle:red", error));
    EXPECT_NE(error.find("found no comparison"), std::string::npos);
    EXPECT_FALSE(splitClaim("1 < 2 < 3", error));
    EXPECT_FALSE(splitClaim(" < 3", error));
    const auto parts = splitClaim("g <= 9.81", error);
    ASSERT_TRUE(parts);
    EXPECT_EQ(parts->left, "g");
    EXPECT_EQ(parts->op, "<=");
    EXPECT_EQ(parts->right, "9.81");
    const auto problems = checkClaim("g < best_angel:red", level, Catalog::builtin());
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].first, 4u) << "the character where the unknown name starts";
    EXPECT_NE(problems[0].second.find("unknown value \"best_angel\""), std::string::npos);
}

TEST(Claims, AnOutcomeCountsTheAimsOfItsFanThatDoWhatTheTextSays)
{
    // 2-6: the first tower (a stone pillar at x = 18), hit high, falls onto the pig on the second (x = 21.5).
    const LevelDef level = loadLevel(kLevels + "2-6-wrecking-crew.json", Catalog::builtin());
    ASSERT_EQ(level.claims.size(), 1u);
    ClaimDef claim = level.claims.front();
    ASSERT_TRUE(claim.outcome.has_value());
    const ClaimResult onto = evaluateClaim(claim, level, Catalog::builtin());
    EXPECT_TRUE(onto.holds) << onto.message;
    EXPECT_GE(onto.aimsThatDo, 7) << onto.message;
    // The same pig felled by a block that stood elsewhere (the third tower) does not count ...
    claim.outcome->byBlockX = std::array<double, 2>{24.5, 25.5};
    EXPECT_EQ(evaluateClaim(claim, level, Catalog::builtin()).aimsThatDo, 0);
    // ... and a shot that misses the tower high up (aimed at the ground in front of it) fells nothing.
    claim.outcome->byBlockX.reset();
    claim.outcome->angleDeg = -10.0;
    const ClaimResult low = evaluateClaim(claim, level, Catalog::builtin());
    EXPECT_FALSE(low.holds);
    EXPECT_EQ(low.aimsThatDo, 0) << low.message;
}

TEST(Claims, StoneThatCannotBreakIsPlayedWithEveryBirdTheLevelHas)
{
    // The teacher's finding: "Stone will not break" on levels with a black bird, whose blast breaks stone. Played with
    // every bird, over a grid of aims and the fan around each, abilities at three moments and unused, such a claim
    // fails and names the bird that breaks it; on the materials lesson (red birds only) a red bird's hit never does.
    const LevelDef keep = loadLevel(kLevels + "4-3-stone-keep.json", Catalog::builtin());
    ClaimDef claim;
    claim.about = "/hints/0";
    claim.cannotBreak = CannotBreakClaimDef{"stone", false};
    const ClaimResult any = evaluateClaim(claim, keep, Catalog::builtin());
    EXPECT_FALSE(any.holds) << any.message;
    EXPECT_GT(any.left, 0.0);
    EXPECT_EQ(any.right, (1.0 + 3.0) * 8 * 3 * 9 + 8 * 3 * 9)
        << "the black bird without its blast and with it at three moments, the red bird without an ability";
    // Only the bird's own hit: the red bird's never breaks stone there, the heavy black bird's seldom does.
    claim.cannotBreak->byBirdOnly = true;
    const ClaimResult hit = evaluateClaim(claim, keep, Catalog::builtin());
    EXPECT_FALSE(hit.holds) << hit.message;
    EXPECT_NE(hit.message.find("by the black bird"), std::string::npos) << hit.message;
    EXPECT_LT(hit.left, any.left);

    const LevelDef lesson = loadLevel(kLevels + "lessons/lesson-materials.json", Catalog::builtin());
    ASSERT_EQ(lesson.claims.size(), 1u);
    ASSERT_TRUE(lesson.claims.front().cannotBreak.has_value());
    EXPECT_TRUE(lesson.claims.front().cannotBreak->byBirdOnly);
    const ClaimResult red = evaluateClaim(lesson.claims.front(), lesson, Catalog::builtin());
    EXPECT_TRUE(red.holds) << red.message;
    // Stone does break there, when a hit topples a post onto the ground: "any cause" is a different promise.
    ClaimDef anyCause = lesson.claims.front();
    anyCause.cannotBreak->byBirdOnly = false;
    EXPECT_FALSE(evaluateClaim(anyCause, lesson, Catalog::builtin()).holds);
}

TEST(Claims, OnlyAnglesNearTheBestThrowTheBirdOntoTheAnglePig)
{
    // The teacher's finding: "Full power only reaches the pig at the best angle" while every angle from 38 to 49
    // degrees won. The lesson's pig now stands at the end of the best throw behind a post too tall to bounce over: at
    // full pull the flight strikes it only within 4 degrees of the best angle, and does at the best.
    const LevelDef lesson = loadLevel(kLevels + "lessons/lesson-angle.json", Catalog::builtin());
    ASSERT_EQ(lesson.claims.size(), 1u);
    ASSERT_TRUE(lesson.claims.front().reach.has_value());
    const ClaimResult now = evaluateClaim(lesson.claims.front(), lesson, Catalog::builtin());
    EXPECT_TRUE(now.holds) << now.message;
    EXPECT_NE(now.message.find("at angles from 41 to 47.5\u00B0"), std::string::npos) << now.message;
    // Within 2 degrees it is false, and says how many angles lie farther out.
    ClaimDef tight = lesson.claims.front();
    tight.reach->withinDeg = 2.0;
    const ClaimResult narrow = evaluateClaim(tight, lesson, Catalog::builtin());
    EXPECT_FALSE(narrow.holds);
    EXPECT_EQ(narrow.left, 6.0) << narrow.message;
    // The geometry the teacher played: the pig 0.8 m nearer behind a 0.8 m post; 37.5 to 50.5 degrees strike it.
    LevelDef before = lesson;
    before.pigs.front().x = 39.5;
    before.blocks.front().y = 0.4;
    before.blocks.front().heightM = 0.8;
    ClaimDef old = lesson.claims.front();
    old.reach->pigX = {39.2, 39.8};
    const ClaimResult wide = evaluateClaim(old, before, Catalog::builtin());
    EXPECT_FALSE(wide.holds);
    EXPECT_NE(wide.message.find("from 37.5 to 50.5\u00B0"), std::string::npos) << wide.message;
    // A pig out of every throw's reach: never struck, so the claim is false rather than empty.
    old.reach->pigX = {60.0, 61.0};
    const ClaimResult none = evaluateClaim(old, lesson, Catalog::builtin());
    EXPECT_FALSE(none.holds);
    EXPECT_NE(none.message.find("never first strikes"), std::string::npos) << none.message;
}

} // namespace
} // namespace abalike
