#pragma once

#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Catalog.hpp>

#include <cstddef>
#include <functional>
#include <vector>

namespace abalike
{

/// Reports how far a long search has got: work items done out of an estimated total.
using ProgressCallback = std::function<void(std::size_t done, std::size_t total)>;

/// How hard the solver searches.
struct SolverOptions
{
    int threads = 0;                                               ///< 0: every hardware thread
    int angleSteps = 37;                                           ///< coarse grid over kMinAngleDeg..kMaxAngleDeg
    std::vector<double> speedFractions{0.45, 0.6, 0.75, 0.9, 1.0}; ///< of each bird's top speed
    int beamWidth = 3;         ///< unfinished shot sequences carried to the next bird
    int refineRounds = 2;      ///< local refinement rounds around the best candidates of each bird
    bool tryAbilities = true;  ///< also try using each bird's ability during its flight
    ProgressCallback progress; ///< called from the solver's threads under a lock; may be empty
};

/// What one shot sequence achieved when played headless.
struct ShotOutcome
{
    bool won = false;
    bool finished = false;
    int score = 0;
    int stars = 0;
    int pigsRemaining = 0;
    int birdsUsed = 0;
};

/// The best shot sequence found.
struct Solution
{
    std::vector<ScriptedShot> shots;
    ShotOutcome outcome;
    std::size_t simulations = 0; ///< shot sequences played
    double seconds = 0.0;        ///< wall time of the search
    /// Pigs (indices in the level's pigs) that the best sequence leaves standing; empty when it wins.
    std::vector<int> survivingPigs;
    /// Pigs that break or take damage with no shot fired (the level does not stand, checkRest): a win would be the
    /// level's own doing, so the solver does not search and the level counts as not won.
    std::vector<int> pigsFallingAlone;
};

/// The outcome of a session, finished or not. On a level with a time limit a win counts only if play ended
/// within the limit.
ShotOutcome outcomeOf(const GameSession& session);

/// Plays a shot sequence with simulateShots and summarises it.
ShotOutcome playShots(const LevelDef& level, const std::vector<ScriptedShot>& shots, const Catalog& catalog);

/// Searches shot sequences (angle, speed, ability timing) bird by bird with a beam search over a coarse grid,
/// refined locally around the best shots, every candidate played headless as simulateShots would play it (going on
/// from the game after the shots before it: SessionBranch, in copies of the process where it can). Candidates are
/// played in parallel but ranked in a fixed order, so the answer does not depend on the number of threads.
Solution solveLevel(const LevelDef& level, const Catalog& catalog = Catalog::builtin(),
                    const SolverOptions& options = {});

} // namespace abalike
