#pragma once

#include <abalike/level/Campaign.hpp>
#include <abalike/save/Progress.hpp>
#include <memory>
#include <string>

namespace abalike
{
class SaveStore;
}

namespace abalike::app
{

struct AppOptions;
class EndlessGame;
class Notices;
class PlayerSettings;
class Trace;

/// The campaign and how far the player got in it: stars, unlocked levels, the endless mode's bests. Results are
/// traced and saved (not in scripted runs).
class PlayerProgress
{
public:
    /// store may be null (no folder for saved games).
    PlayerProgress(Campaign campaign, const AppOptions& options, SaveStore* store, const PlayerSettings& settings,
                   Trace& trace, Notices& notices);
    ~PlayerProgress();

    const Campaign& campaign() const { return m_campaign; }
    const Progress& current() const { return m_progress; }
    /// Whether the player may start this campaign level (a teacher may open every level for a class).
    bool isUnlocked(const std::string& levelId) const;
    /// Records a finished level (best score and stars, unlocks the next) and saves it.
    void recordResult(const std::string& levelId, int score, int stars);
    /// The endless mode of this session, started (its worker with it) the first time it is asked for.
    EndlessGame& endless();
    /// The endless run has won `levelsWon` levels for `score` points (ended: the run is over, lost): keeps the
    /// player's bests and saves them.
    void recordEndless(int levelsWon, int score, bool ended);

private:
    void save();

    Campaign m_campaign;
    const AppOptions& m_options;
    SaveStore* m_store;
    const PlayerSettings& m_settings;
    Trace& m_trace;
    Notices& m_notices;
    Progress m_progress;
    std::unique_ptr<EndlessGame> m_endless;
};

} // namespace abalike::app
