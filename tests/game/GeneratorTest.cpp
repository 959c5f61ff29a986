#include <abalike/design/GeneratorLayouts.hpp>

#include "../SanitizerBuild.hpp"

#include <abalike/design/Generator.hpp>
#include <abalike/design/LayoutTwins.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/level/WorldTheme.hpp>
#include <abalike/world/RestCheck.hpp>

#include <atomic>
#include <chrono>
#include <gtest/gtest.h>
#include <map>
#include <set>
#include <thread>

namespace abalike
{
namespace
{

const std::vector<GeneratorPart>& bundledParts()
{
    static const std::vector<GeneratorPart> parts =
        loadGeneratorParts(std::string(ABALIKE_SOURCE_DIR) + "/levels/parts", Catalog::builtin());
    return parts;
}

TEST(GeneratorRng, ASeedAndStreamNameOneSequence)
{
    GeneratorRng a(4711, 3);
    GeneratorRng b(4711, 3);
    GeneratorRng other(4711, 4);
    int differs = 0;
    for (int i = 0; i < 100; ++i)
    {
        const double x = a.metres(1.5, 3.0);
        EXPECT_EQ(x, b.metres(1.5, 3.0));
        EXPECT_GE(x, 1.5);
        EXPECT_LE(x, 3.0);
        EXPECT_DOUBLE_EQ(x * 100.0, std::round(x * 100.0)) << "whole centimetres";
        differs += x != other.metres(1.5, 3.0) ? 1 : 0;
    }
    EXPECT_GT(differs, 90);
    // SplitMix64 is fully specified: its first output for this state is a fixed number on every platform.
    EXPECT_EQ(GeneratorRng(1, 0).next(), GeneratorRng(1, 0).next());
}

TEST(Generator, LayoutsCoverEveryKindWithinTheBudgetAndMostStand)
{
    std::set<GeneratedKind> kinds;
    std::map<GeneratedKind, int> standing;
    std::map<GeneratedKind, int> laidOut;
    for (std::uint64_t stream = 0; stream < 48; ++stream)
    {
        GeneratorRng rng(7, stream);
        LevelDef level;
        const GeneratedKind kind = layOut(level, bundledParts(), rng, Catalog::builtin());
        kinds.insert(kind);
        const std::size_t bodies = level.blocks.size() + level.pigs.size();
        EXPECT_LE(bodies, static_cast<std::size_t>(GeneratorOptions::kMaxBodies)) << stream;
        EXPECT_GE(bodies, 12u) << stream;
        EXPECT_FALSE(level.pigs.empty()) << stream;
        for (const BlockDef& block : level.blocks)
            EXPECT_GE(block.x, 15.0) << "structures stand clear of the slingshot, stream " << stream;
        ++laidOut[kind];
        standing[kind] += checkRest(level).passed() ? 1 : 0;
    }
    EXPECT_EQ(kinds.size(), generatedKinds().size());
    // Parts stand on their own (levels_match_generator); put side by side, on hills and islands, they still do.
    for (const auto& [kind, count] : laidOut)
        EXPECT_EQ(standing[kind], count) << generatedKindName(kind);
}

TEST(Generator, ALevelIsVerifiedAndTheSameSeedGivesTheSameBytesWhateverTheThreads)
{
    if (test::kSanitizerBuild)
        GTEST_SKIP() << "two verified generations take minutes under the sanitizers; the Release stage runs them";
    GeneratorOptions options;
    options.seed = 6;
    options.lossShare = 0.5;
    options.playerRuns = 12; // a short measure; the command's default is 40
    options.threads = 1;
    const GeneratedLevel one = generateLevel(bundledParts(), options);
    options.threads = 2;
    const GeneratedLevel two = generateLevel(bundledParts(), options);
    ASSERT_TRUE(one.ok) << one.attempts;
    EXPECT_EQ(writeLevelJson(one.level, "s"), writeLevelJson(two.level, "s"));
    EXPECT_TRUE(checkRest(one.level).passed());
    EXPECT_TRUE(one.solution.outcome.won);
    EXPECT_NEAR(one.lossShare, options.lossShare, GeneratorOptions::kLossTolerance);
    EXPECT_EQ(one.attempts, static_cast<int>(one.rejected.size()) + 1);
    ASSERT_TRUE(one.level.referenceShot);
    EXPECT_EQ(one.level.referenceShot->angleDeg, one.solution.shots.front().angleDeg);
    // "TNT store 6": the kind and the seed (which kind a seed gives is the build's: its floating point decides).
    EXPECT_EQ(one.level.title.substr(one.level.title.rfind(' ')), " 6");
}

TEST(Generator, TheStopFlagEndsAGenerationWithinASecondOrTwo)
{
    std::atomic<bool> stop{true};
    GeneratorOptions options;
    options.seed = 6;
    options.threads = 1;
    options.stop = &stop;
    const GeneratedLevel stoppedBefore = generateLevel(bundledParts(), options);
    EXPECT_TRUE(stoppedBefore.stopped);
    EXPECT_FALSE(stoppedBefore.ok);
    EXPECT_EQ(stoppedBefore.attempts, 0);

    // Stopped while the solver and the model player work (a whole generation takes half a minute and more).
    stop = false;
    std::thread stopper(
        [&stop]
        {
            std::this_thread::sleep_for(std::chrono::milliseconds(300));
            stop = true;
        });
    const auto start = std::chrono::steady_clock::now();
    const GeneratedLevel stoppedDuring = generateLevel(bundledParts(), options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stopper.join();
    EXPECT_TRUE(stoppedDuring.stopped);
    EXPECT_FALSE(stoppedDuring.ok);
    EXPECT_LT(seconds, test::kSanitizerBuild ? 60.0 : 15.0) << "one model-player run or solver shot at most";
}

TEST(Generator, GenerateHereGivesEveryKindWithinItsSizeStanding)
{
    for (const GeneratedKind kind : generatedKinds())
        for (const int size : {12, 20, 30})
        {
            SCOPED_TRACE(std::string(generatedKindName(kind)) + " " + std::to_string(size));
            const std::optional<LevelDef> structure =
                generateStructure(bundledParts(), kind, size, 3, Catalog::builtin());
            ASSERT_TRUE(structure) << generatedKindName(kind) << " " << size;
            const std::size_t bodies = structure->blocks.size() + structure->pigs.size();
            EXPECT_LE(bodies, static_cast<std::size_t>(size)) << generatedKindName(kind);
            EXPECT_GE(bodies, 3u) << generatedKindName(kind);
            EXPECT_FALSE(structure->pigs.empty()) << generatedKindName(kind);
            EXPECT_TRUE(checkRest(*structure).passed()) << generatedKindName(kind);
            EXPECT_EQ(kind == GeneratedKind::Hill || kind == GeneratedKind::Island, !structure->terrain.empty());
        }
}

TEST(Generator, LayoutDistanceIsZeroForTheSameLayoutMovedAndGrowsWithDifference)
{
    LevelDef a;
    a.blocks.push_back({BlockShape::Box, "wood", 20.0, 1.0, 0.25, 2.0, 0.0, 0.1});
    a.pigs.push_back({"small", 21.0, 0.25});
    LevelDef moved = a;
    for (BlockDef& b : moved.blocks)
        b.x += 7.3;
    for (PigDef& p : moved.pigs)
        p.x += 7.3;
    EXPECT_DOUBLE_EQ(layoutDistance(a, moved, Catalog::builtin()), 0.0);
    LevelDef taller = a;
    taller.blocks.push_back({BlockShape::Box, "wood", 20.0, 3.0, 0.25, 2.0, 0.0, 0.1});
    const double grown = layoutDistance(a, taller, Catalog::builtin());
    EXPECT_GT(grown, 0.3);
    EXPECT_LT(grown, 0.7); // half its cells are the first one's
    LevelDef apart;
    apart.blocks.push_back({BlockShape::Box, "stone", 20.0, 5.0, 0.25, 2.0, 0.0, 0.1}); // in the air: no cell shared
    EXPECT_DOUBLE_EQ(layoutDistance(a, apart, Catalog::builtin()), 1.0);
}

TEST(Generator, LayoutTwinsAreTheSamePartsAFewTenthsApartWhateverTheirMaterials)
{
    // A frame (two posts and a plank, a pig inside) and a box beside it.
    LevelDef a;
    a.blocks = {{BlockShape::Box, "wood", 20.0, 1.0, 0.25, 2.0, 0.0, 0.1},
                {BlockShape::Box, "wood", 22.0, 1.0, 0.25, 2.0, 0.0, 0.1},
                {BlockShape::Box, "wood", 21.0, 2.125, 2.6, 0.25, 0.0, 0.1},
                {BlockShape::Box, "ice", 24.2, 0.6, 1.2, 1.2, 0.0, 0.1}};
    a.pigs = {{"small", 21.0, 0.25}};
    // The box 0.3 m nearer and the plank of stone: the grid sees a difference, a player does not.
    LevelDef nearer = a;
    nearer.blocks[3].x -= 0.3;
    nearer.blocks[2].material = "stone";
    EXPECT_GT(layoutDistance(a, nearer, Catalog::builtin()), 0.0);
    EXPECT_DOUBLE_EQ(layoutTwinShare(a, nearer), 1.0);
    // The box 2 m further: one body of five has no partner, so they are not twins.
    LevelDef apart = a;
    apart.blocks[3].x += 2.0;
    EXPECT_DOUBLE_EQ(layoutTwinShare(a, apart), 0.8);
    EXPECT_LT(layoutTwinShare(a, apart), kTwinShare);
    // A larger pig is another body; a level with nothing is twin to none.
    LevelDef largerPig = a;
    largerPig.pigs[0].type = "large";
    EXPECT_DOUBLE_EQ(layoutTwinShare(a, largerPig), 0.8);
    EXPECT_DOUBLE_EQ(layoutTwinShare(a, LevelDef{}), 0.0);
    // Counted both ways: an extra block makes the larger level's share the smaller one.
    LevelDef extra = a;
    extra.blocks.push_back({BlockShape::Box, "stone", 26.0, 0.5, 1.0, 1.0, 0.0, 0.1});
    EXPECT_DOUBLE_EQ(layoutTwinShare(a, extra), 5.0 / 6.0);
}

TEST(Generator, FortyLayoutsOfEachKindHaveNoTwinsAndMostStand)
{
    // The 200-level variety run asks that no two levels look alike; its levels come about 25 of a kind. Forty of each
    // kind with no layout twins (bodies of the same shape and size in the same places) leaves it a margin.
    constexpr std::uint64_t kSeeds = 40;
    for (const GeneratedKind kind : generatedKinds())
    {
        std::vector<LevelDef> levels;
        int standing = 0;
        for (std::uint64_t seed = 1; seed <= kSeeds; ++seed)
        {
            GeneratorRng rng(seed, 0);
            LevelDef level;
            layOut(level, bundledParts(), rng, Catalog::builtin(), kind);
            standing += checkRest(level).passed() ? 1 : 0;
            levels.push_back(level);
        }
        for (std::size_t i = 0; i < levels.size(); ++i)
            for (std::size_t j = i + 1; j < levels.size(); ++j)
                if (layoutTwinShare(levels[i], levels[j]) >= kTwinShare)
                    ADD_FAILURE() << generatedKindName(kind) << ": seeds " << i + 1 << " and " << j + 1
                                  << " are layout twins (" << layoutTwinShare(levels[i], levels[j]) << ")";
        EXPECT_GE(standing, static_cast<int>(kSeeds) * 3 / 4) << generatedKindName(kind);
    }
}

TEST(Generator, TheWorldSetsGravityAirLookAndBand)
{
    LevelDef moon;
    applyGeneratorWorld(moon, "moon");
    EXPECT_DOUBLE_EQ(moon.environment.gravity, 1.62);
    EXPECT_DOUBLE_EQ(moon.environment.airDensity, 0.0);
    EXPECT_EQ(moon.theme, WorldTheme::Moon);
    EXPECT_FALSE(moon.slingshot.ownsBand()) << "the Moon's band, from the catalog";
    EXPECT_DOUBLE_EQ(levelBand(moon, Catalog::builtin()).maxForceN, 2756.25);
    LevelDef jupiter;
    applyGeneratorWorld(jupiter, "jupiter");
    EXPECT_DOUBLE_EQ(levelBand(jupiter, Catalog::builtin()).maxForceN, 22500.0);
    LevelDef earth;
    applyGeneratorWorld(earth, "earth");
    EXPECT_EQ(earth, LevelDef{});
    GeneratorOptions options;
    options.world = "pluto";
    EXPECT_THROW(generateLevel(bundledParts(), options), std::invalid_argument);
    options.world = "earth";
    options.birds = {"red", "grey"};
    EXPECT_THROW(generateLevel(bundledParts(), options), std::invalid_argument);
    EXPECT_THROW(generateLevel({}, GeneratorOptions{}), std::invalid_argument);
}

} // namespace
} // namespace abalike
