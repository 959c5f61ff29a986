#include <abalike/design/ModelPlayer.hpp>
#include <abalike/design/Solver.hpp>
#include <abalike/game/SessionBranch.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/util/Bytes.hpp>
#include <abalike/util/ProcessCopy.hpp>
#include <abalike/world/WorldDigest.hpp>
#include <gtest/gtest.h>

#include <stdexcept>

namespace abalike
{
namespace
{

LevelDef level(const std::string& name)
{
    return loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/" + name, Catalog::builtin());
}

/// What a trial reads: the score, the pigs left, the end of play and every body's exact state.
std::string fingerprint(const GameSession& session)
{
    return BytesOut().put(session.score().total()).put(session.pigsRemaining()).put(session.simTime()).take() +
           bodiesDigest(session.world());
}

/// Copies allowed again when a test ends, however it ends.
struct CopiesAllowed
{
    ~CopiesAllowed() { allowProcessCopies(true); }
};

TEST(ProcessCopy, WorkChangesNothingHereAndItsBytesComeBack)
{
    ASSERT_TRUE(processCopiesAvailable()); // Linux: the searches rely on it for their speed
    int value = 1;
    const ProcessCopyCounts before = processCopyCounts();
    const auto bytes = runInProcessCopy(
        [&]
        {
            value = 2;
            return std::string("changed to ") + std::to_string(value);
        });
    ASSERT_TRUE(bytes);
    EXPECT_EQ(*bytes, "changed to 2");
    EXPECT_EQ(value, 1);
    EXPECT_EQ(processCopyCounts().made, before.made + 1);
    EXPECT_EQ(processCopyCounts().failed, before.failed);
}

TEST(ProcessCopy, ACopyWhoseWorkThrowsGivesNothingAndIsCounted)
{
    const ProcessCopyCounts before = processCopyCounts();
    EXPECT_FALSE(runInProcessCopy([]() -> std::string { throw std::runtime_error("no"); }));
    EXPECT_EQ(processCopyCounts().failed, before.failed + 1);
    CopiesAllowed restore;
    allowProcessCopies(false);
    EXPECT_FALSE(runInProcessCopy([] { return std::string("x"); }));
}

TEST(ProcessCopy, CopiesWorkEveryItemOnceAndReportEach)
{
    std::vector<int> reported;
    const auto results = runInProcessCopies(
        7, 3,
        [](std::size_t i)
        {
            if (i == 4)
                throw std::runtime_error("item 4 fails in its copy");
            return std::string(i + 1, 'a');
        },
        [&](std::size_t i) { reported.push_back(static_cast<int>(i)); });
    ASSERT_TRUE(results);
    ASSERT_EQ(results->size(), 7u);
    for (std::size_t i = 0; i < 7; ++i)
        if (i == 4)
            EXPECT_FALSE((*results)[i]);
        else
            EXPECT_EQ((*results)[i], std::string(i + 1, 'a'));
    EXPECT_EQ(reported.size(), 6u);
}

TEST(SessionBranch, ATrialOnACopyIsTheReplayBitForBit)
{
    // 4-8 after the solver's first two shots (a moving, half-broken structure): the first two trials of a branch
    // are played on copies, the next two again from the start; all four equal simulateShots.
    const LevelDef l = level("4-8-cold-feet.json");
    const std::vector<ScriptedShot> prefix{{5.6, 28.5}, {10.0, 27.0}};
    const SessionBranch branch(l, prefix, Catalog::builtin());
    const ProcessCopyCounts before = processCopyCounts();
    for (const ScriptedShot shot : {ScriptedShot(72.5, 26.83, 3.7), ScriptedShot(30.0, 20.0),
                                    ScriptedShot(72.5, 26.83, 3.7), ScriptedShot(30.0, 20.0)})
    {
        std::vector<ScriptedShot> all = prefix;
        all.push_back(shot);
        EXPECT_EQ(branch.trial(shot, fingerprint), fingerprint(*simulateShots(l, all, Catalog::builtin())))
            << shot.angleDeg;
    }
    EXPECT_EQ(processCopyCounts().made, before.made + 2);
    EXPECT_EQ(processCopyCounts().failed, before.failed);
    EXPECT_EQ(branch.shots().size(), 2u);
    EXPECT_EQ(branch.session().birdsUsed(), 2);
}

TEST(SessionBranch, ARefusedShotIsALaunchErrorOnACopyToo)
{
    const LevelDef l = level("1-1-first-flight.json");
    const SessionBranch branch(l, {{45.0, 10.0}}, Catalog::builtin());
    // The red bird has no ability to use.
    EXPECT_THROW(branch.trial({45.0, 10.0, 0.5}, fingerprint), LaunchError);
}

TEST(SessionBranch, SearchesGiveTheSameAnswerWithAndWithoutCopies)
{
    CopiesAllowed restore;
    const LevelDef l = level("2-8-dominoes.json");
    ModelPlayerOptions options;
    options.runs = 3;
    options.threads = 2;
    const PlayerDifficulty copied = measurePlayerDifficulty(l, Catalog::builtin(), options);
    allowProcessCopies(false);
    const PlayerDifficulty replayed = measurePlayerDifficulty(l, Catalog::builtin(), options);
    EXPECT_EQ(copied.winScores, replayed.winScores);
    EXPECT_EQ(copied.wins, replayed.wins);
    EXPECT_EQ(copied.simulations, replayed.simulations);
}

} // namespace
} // namespace abalike
