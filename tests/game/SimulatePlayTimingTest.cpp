#include <abalike/game/GameSession.hpp>
#include <abalike/game/ShotSequence.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/level/ScienceBirds.hpp>
#include <abalike/world/WorldDigest.hpp>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

// The simulate/play timing contract (docs/cli.md): `abalike play --shot` replays what `abalike simulate` computes.
// Both drive a ShotSequence; the window adds a hold before each shot (its preview shows) and steps the world itself
// whenever the script has nothing to do. Here the window's loop runs headless, step by step as PlayScreen does it,
// beside simulateShots, and the two must end with the same defeats at the same times, score and bodies.

namespace abalike
{
namespace
{

/// The window's loop (PlayScreen::physicsStep): the script's step, else the world's own, until the level is decided
/// or the script is played out (simulate stops there; the window goes on waiting for the player).
std::unique_ptr<GameSession> playLikeTheWindow(const LevelDef& level, const std::vector<ScriptedShot>& shots)
{
    auto session = std::make_unique<GameSession>(level);
    ShotSequence script(shots, 0.5);
    int held = 0;
    for (;;)
    {
        const ShotSequence::Tick tick = script.advance(*session, session->world().dt());
        held += tick == ShotSequence::Tick::Held;
        if (tick == ShotSequence::Tick::Idle)
            break;
    }
    // A 0.5 s hold is 29 steps waited, the shot firing on the 30th: the world never stepped in them.
    EXPECT_EQ(held, 29 * session->birdsUsed());
    return session;
}

void expectSameRun(const LevelDef& level, const std::vector<ScriptedShot>& shots)
{
    const std::unique_ptr<GameSession> simulated = simulateShots(level, shots);
    const std::unique_ptr<GameSession> played = playLikeTheWindow(level, shots);
    EXPECT_EQ(played->phase(), simulated->phase());
    EXPECT_EQ(played->score().total(), simulated->score().total());
    EXPECT_EQ(played->stars(), simulated->stars());
    EXPECT_EQ(played->birdsUsed(), simulated->birdsUsed());
    EXPECT_EQ(played->simTime(), simulated->simTime());
    const std::vector<DestroyedEvent> a = simulated->defeats();
    const std::vector<DestroyedEvent> b = played->defeats();
    ASSERT_EQ(b.size(), a.size());
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        EXPECT_EQ(b[i].timeS, a[i].timeS) << "defeat " << i;
        EXPECT_EQ(b[i].kind, a[i].kind) << "defeat " << i;
        EXPECT_EQ(b[i].index, a[i].index) << "defeat " << i;
    }
    EXPECT_EQ(bodiesDigest(played->world()), bodiesDigest(simulated->world()));
}

std::string sourcePath(const std::string& relative)
{
    return std::string(ABALIKE_SOURCE_DIR) + "/" + relative;
}

TEST(SimulatePlayTiming, EveryCampaignLevelsReferenceShotEndsTheSame)
{
    const std::vector<std::string> paths = loadCampaign(sourcePath("levels/campaign.json"));
    ASSERT_EQ(paths.size(), 50u);
    for (const std::string& path : paths)
    {
        SCOPED_TRACE(path);
        const LevelDef level = loadLevel(path, Catalog::builtin());
        ASSERT_TRUE(level.referenceShot);
        expectSameRun(level, {ScriptedShot(level.referenceShot->angleDeg, level.referenceShot->speedMps)});
    }
}

TEST(SimulatePlayTiming, TheSolversWinsOnTenGeneratedLevelsReplay)
{
    std::ifstream in(sourcePath("tests/game/data/solver-wins.json"));
    const nlohmann::json wins = nlohmann::json::parse(in);
    ASSERT_EQ(wins["levels"].size(), 10u);
    for (const nlohmann::json& entry : wins["levels"])
    {
        SCOPED_TRACE(entry["path"].get<std::string>());
        const LevelDef level = loadLevel(sourcePath(entry["path"]), Catalog::builtin());
        std::vector<ScriptedShot> shots;
        for (const nlohmann::json& shot : entry["shots"])
            shots.emplace_back(shot[0].get<double>(), shot[1].get<double>(),
                               shot.size() > 2 ? std::optional(shot[2].get<double>()) : std::nullopt);
        EXPECT_GE(shots.size(), 1u);
        EXPECT_EQ(simulateShots(level, shots)->phase(), Phase::Won) << "the solver's sequence no longer wins";
        expectSameRun(level, shots);
    }
}

TEST(SimulatePlayTiming, ImportedScienceBirdsLevelsEndTheSame)
{
    // Every bird fired in turn, low and fast then high: the structures are hit, fall and settle between shots.
    const std::filesystem::path folder = sourcePath("tests/level/science-birds");
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
    {
        if (entry.path().extension() != ".xml")
            continue;
        SCOPED_TRACE(entry.path().filename().string());
        std::ifstream in(entry.path(), std::ios::binary);
        const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        const ScienceBirdsLevel imported =
            importScienceBirds(bytes, entry.path().filename().string(), Catalog::builtin(), ScienceBirdsOptions{true});
        std::vector<ScriptedShot> shots;
        for (std::size_t i = 0; i < imported.level.birds.size(); ++i)
        {
            const BirdType* bird = Catalog::builtin().findBird(imported.level.birds[i]);
            ASSERT_NE(bird, nullptr);
            const double top = maxLaunchSpeed(imported.level, *bird, Catalog::builtin());
            shots.emplace_back(i % 2 == 0 ? 15.0 : 40.0, (i % 2 == 0 ? 0.95 : 0.8) * top);
        }
        ++files;
        expectSameRun(imported.level, shots);
    }
    EXPECT_GE(files, 5u);
}

} // namespace
} // namespace abalike
