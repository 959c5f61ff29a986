#pragma once

#include <abalike/design/GeneratedLevelQueue.hpp>
#include <abalike/game/EndlessRun.hpp>
#include <abalike/level/LevelDef.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

/// One level of the endless mode. Its seed and loss share name it: `play --generated SEED:L` replays it.
struct EndlessLevel
{
    LevelDef level;
    std::uint64_t seed = 0;
    int lossShareTenths = 0;
    bool shipped = false; ///< from levels/endless/ (the first of a session), not generated while playing

    /// "4711:0.3", what `play --generated` takes.
    std::string generatedName() const;
};

/// The levels of levels/endless/, each named SEED-L.json as `abalike generate --seed SEED --loss-share L` wrote
/// it, sorted by name. Throws LevelLoadError for a file that does not load or is named otherwise.
std::vector<EndlessLevel> loadShippedEndlessLevels(const std::filesystem::path& folder);

/// The endless mode of one game session: the run (EndlessRun), the shipped levels and the levels generated ahead on
/// a low-priority worker (GeneratedLevelQueue), each also written to the cache folder, where `play --generated`
/// finds it. The worker starts with the first level and stops when the game quits.
class EndlessGame
{
public:
    /// levels: the data folder's levels/ (endless/ and parts/); cache: where generated levels are kept (the
    /// cache folder's generated/); firstSeed: the first generated level's seed; runsEnded: the player's runs so
    /// far (the session's first level rotates through the shipped ones by it); scripted: a scripted run, whose
    /// frames must not depend on how fast the worker is (every shipped level first, then each generated level
    /// waited for).
    EndlessGame(const std::filesystem::path& levels, std::filesystem::path cache, std::uint64_t firstSeed,
                int runsEnded, bool scripted = false);
    ~EndlessGame();

    /// The level to play at the run's loss share: one generated ahead if it is ready, else a shipped one not yet
    /// played this session, the nearest in loss share; none when neither is there yet (ask again each frame). Asks
    /// the worker for the loss shares of the level after it.
    std::optional<EndlessLevel> nextLevel();
    const EndlessRun& run() const { return m_run; }
    /// The level was won: the run goes on, harder.
    void won(int score)
    {
        m_playing = false;
        m_run.won(score);
    }
    /// The level was lost: the run ends (returned), the next starts easier.
    EndlessRun::Result lost()
    {
        m_playing = false;
        return m_lastEnded = m_run.lost();
    }
    /// A level was handed out and neither won nor lost yet: asking for the next one leaves it, which counts as a
    /// loss (the caller records it), so that leaving a castle that is going badly cannot save a run.
    bool playing() const { return m_playing; }
    /// What the last run to end achieved.
    const EndlessRun::Result& lastRunEnded() const { return m_lastEnded; }
    /// What the worker is doing, for the waiting card.
    GeneratedLevelQueue::Status generation() const;
    /// The player waits for the level (the waiting card is up): the worker uses every core until it is false again.
    void hurry(bool hurry) { m_queue->hurry(hurry); }
    /// Why the mode cannot run (a shipped level that does not load, no castle parts), empty when it can.
    const std::string& problem() const { return m_problem; }

private:
    std::optional<EndlessLevel> shippedLevel(int tenths);

    std::filesystem::path m_cache;
    std::vector<EndlessLevel> m_shipped;
    std::vector<bool> m_played;
    int m_runsEnded = 0;
    bool m_scripted = false;
    EndlessRun m_run;
    EndlessRun::Result m_lastEnded;
    bool m_playing = false;
    std::string m_problem;
    std::unique_ptr<GeneratedLevelQueue> m_queue;
};

} // namespace abalike::app
