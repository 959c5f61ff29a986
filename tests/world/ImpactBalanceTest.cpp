// The first impact's momentum balance: the bird's and the struck body's changes of momentum equal the impulses from
// outside the pair (what the body rests on, gravity, the break rule), measured one by one from Box2D's contact
// impulses, so a class checking conservation on any shot finds it.
#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

const std::string kLevels = std::string(ABALIKE_SOURCE_DIR) + "/levels/";

/// Launches one shot and steps until the bird's first contact (or the end of the shot).
std::optional<FirstImpact> firstImpact(const LevelDef& level, double angleDeg, double speedMps)
{
    GameSession session(level);
    session.launch(angleDeg, speedMps);
    while (session.phase() == Phase::Flying && !session.world().birdContact())
        session.step();
    return session.world().birdImpact();
}

double length(const Vec2& v)
{
    return std::hypot(v.x, v.y);
}

/// Box2D works in float: the balance closes to 1e-3 kg m/s or 1e-5 of the bird's momentum, whichever is larger.
void expectBalanced(const FirstImpact& impact, const std::string& where)
{
    const double birdMomentum = impact.birdMassKg * std::hypot(impact.birdBefore.vx, impact.birdBefore.vy);
    const double tolerance = std::max(1e-3, 1e-5 * birdMomentum);
    const auto residual = impact.balanceResidual();
    EXPECT_LE(length(residual), tolerance)
        << where << ": residual (" << residual.x << ", " << residual.y << ") kg m/s; bird change ("
        << impact.birdChange().x << ", " << impact.birdChange().y << "), body change (" << impact.bodyChange().x << ", "
        << impact.bodyChange().y << "), supports (" << impact.balance.supports.x << ", " << impact.balance.supports.y
        << "), gravity (" << impact.balance.gravity.x << ", " << impact.balance.gravity.y << ")";
}

TEST(ImpactBalance, ClosesOnEveryCampaignLevelsAndLessonsReferenceShot)
{
    std::vector<std::string> paths = loadCampaign(kLevels + "campaign.json");
    for (const auto& entry : std::filesystem::directory_iterator(kLevels + "lessons"))
        if (entry.path().extension() == ".json")
            paths.push_back(entry.path().string());
    int impacts = 0;
    int supported = 0;
    int broken = 0;
    for (const std::string& path : paths)
    {
        const LevelDef level = loadLevel(path, Catalog::builtin());
        if (!level.referenceShot)
            continue;
        const auto impact = firstImpact(level, level.referenceShot->angleDeg, level.referenceShot->speedMps);
        if (!impact)
            continue;
        ++impacts;
        expectBalanced(*impact, level.id);
        // The balance has something to show: many struck bodies stand on something that pushes back.
        if (length(impact->balance.supports) > 0.05 * length(impact->balance.pushOnBody))
            ++supported;
        broken += impact->broke ? 1 : 0;
    }
    EXPECT_GE(impacts, 40) << "most reference shots first hit a block or a pig";
    EXPECT_GE(supported, 15) << "measured: 20 of 52";
    EXPECT_GE(broken, 10);
}

TEST(ImpactBalance, TheMomentumLessonsShotShowsTheBlockHeldByWhatItStandsOn)
{
    // The teacher's finding: the bird lost (-59.4, +9.9) kg m/s and the block was shown with (31.7, 51.1). The
    // difference is what the block stands on pushing back (and the break giving part of the push back).
    const LevelDef level = loadLevel(kLevels + "lessons/lesson-momentum.json", Catalog::builtin());
    const auto impact = firstImpact(level, level.referenceShot->angleDeg, level.referenceShot->speedMps);
    ASSERT_TRUE(impact);
    expectBalanced(*impact, level.id);
    EXPECT_GT(impact->balance.supports.y, 0.5 * impact->bodyChange().y) << "the support lifts the block";
    // Newton's third law between the two: the bird's change is the opposite of its push, plus what the break gave
    // back to it.
    const double refundX = impact->birdChange().x + impact->balance.pushOnBody.x;
    EXPECT_GE(refundX, -1e-3);
    EXPECT_EQ(impact->broke, refundX > 1e-3);
}

/// A pig on the ground, hit from above and in front: the ground pins it.
LevelDef pinnedPig()
{
    return parseLevel(R"({"format": 1, "id": "pinned", "title": "pinned", "ground": {"y": 0.0},
        "slingshot": {"x": 0.0, "y": 8.0}, "birds": ["black"],
        "pigs": [{"type": "large", "x": 12.0, "y": 0.5}], "stars": [1, 2, 3]})",
                      "pinned.json", Catalog::builtin());
}

TEST(ImpactBalance, APigPinnedAgainstTheGroundLeavesUpwardAndTheGroundsShareSaysWhy)
{
    const LevelDef level = pinnedPig();
    // Steeply down onto the pig: the bird's push is mostly downward.
    const auto impact = firstImpact(level, -20.0, 16.0);
    ASSERT_TRUE(impact);
    ASSERT_EQ(impact->bodyKind, EntityKind::Pig);
    expectBalanced(*impact, "pinned pig");
    EXPECT_LT(impact->balance.pushOnBody.y, 0.0) << "the bird pushed the pig down";
    EXPECT_GT(impact->balance.supports.y, -0.95 * impact->balance.pushOnBody.y) << "the ground pushed back";
    EXPECT_GE(impact->bodyChange().y, 0.0) << "so the pig does not go down";
}

TEST(ImpactBalance, AFloatingBodyHasNoSupportAndKeepsMomentum)
{
    const LevelDef level = parseLevel(R"({"format": 1, "id": "t", "title": "zero g", "environment": {"gravity": 0.0},
        "ground": {"y": 0.0}, "slingshot": {"x": 0.0, "y": 5.0, "max_force_n": 1200, "band_mass_kg": 0}, "birds": ["red"],
        "blocks": [{"material": "stone", "x": 10.0, "y": 5.0, "w": 1.0, "h": 1.0}],
        "pigs": [{"type": "small", "x": 30.0, "y": 0.35}], "stars": [1, 2, 3]})",
                                      "zero-g.json", Catalog::builtin());
    const auto impact = firstImpact(level, 0.0, 20.0);
    ASSERT_TRUE(impact);
    expectBalanced(*impact, "zero g");
    EXPECT_EQ(length(impact->balance.supports), 0.0);
    EXPECT_EQ(length(impact->balance.gravity), 0.0);
    EXPECT_NEAR(impact->birdChange().x, -impact->balance.pushOnBody.x, 1e-4);
    EXPECT_GT(impact->balance.pushOnBody.x, 10.0);
}

TEST(ImpactBalance, AnAwakeBodysWeightOverTheStepIsCounted)
{
    // Fired at once at a block beside the slingshot: the level was settled a moment ago, so its bodies are still
    // awake and Box2D integrates their weight in the impact's step.
    const LevelDef level = parseLevel(R"({"format": 1, "id": "t", "title": "near", "ground": {"y": 0.0},
        "slingshot": {"x": 0.0, "y": 1.0}, "birds": ["red"],
        "blocks": [{"material": "wood", "x": 2.5, "y": 1.0, "w": 0.5, "h": 2.0}],
        "pigs": [{"type": "small", "x": 30.0, "y": 0.35}], "stars": [1, 2, 3]})",
                                      "near.json", Catalog::builtin());
    const auto impact = firstImpact(level, 0.0, 15.0);
    ASSERT_TRUE(impact);
    expectBalanced(*impact, "awake block");
    EXPECT_LT(impact->balance.gravity.y, 0.0);
    EXPECT_NEAR(impact->balance.gravity.y, -impact->bodyMassKg * 9.81 / 60.0, 1e-3 * impact->bodyMassKg);
}

} // namespace
} // namespace abalike
