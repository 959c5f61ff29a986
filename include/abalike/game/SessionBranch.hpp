#pragma once

#include <abalike/game/GameSession.hpp>

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace abalike
{

/// A game played headless up to the end of a turn, from which searches try many next shots (the solver's candidates,
/// the model player's aims). A trial plays one more shot to the end of its turn on a copy of the session and gives
/// what it read there: exactly what simulateShots(level, shots() + {shot}) would give, bit for bit, without playing
/// the shots before again. The copy is a copy of the process (runInProcessCopy); where there is none, or where
/// playing the shots again has been quicker than copying, the trial plays every shot from the start, as
/// simulateShots does.
class SessionBranch
{
public:
    /// What a trial reads from the session once its shot's turn is over: plain bytes (BytesOut), since it may run
    /// in another process.
    using Read = std::function<std::string(const GameSession&)>;

    /// Plays shots on the level as simulateShots does (throws LaunchError as it does).
    SessionBranch(const LevelDef& level, std::vector<ScriptedShot> shots, const Catalog& catalog);

    const std::vector<ScriptedShot>& shots() const { return m_shots; }
    const GameSession& session() const { return *m_session; }

    /// Plays one more shot on the branch itself, to the end of its turn.
    void play(const ScriptedShot& shot);

    /// read(session) after one more shot, played on a copy: the branch is left as it is, so trials may run on
    /// several threads at once. Throws LaunchError when the shot cannot be fired, as simulateShots does.
    std::string trial(const ScriptedShot& shot, const Read& read) const;

private:
    const LevelDef& m_level;
    const Catalog& m_catalog;
    std::vector<ScriptedShot> m_shots;
    std::unique_ptr<GameSession> m_session;

    /// What trials have cost each way on this branch. A copy's cost is its making and the memory pages the trial
    /// then writes (milliseconds on a virtual machine), a replay's the shots before: which is less depends on the
    /// level and the machine, and the answer is the same either way.
    class TrialCosts
    {
    public:
        /// Whether the next trial should be played on a copy.
        bool copyNext(bool canCopy);
        void addCopy(double seconds);
        void addReplay(double seconds);

    private:
        static constexpr int kTries = 2;
        std::mutex m_mutex;
        double m_copyS = 0.0;
        double m_replayS = 0.0;
        int m_copies = 0;
        int m_replays = 0;
    };
    mutable TrialCosts m_costs;
};

} // namespace abalike
