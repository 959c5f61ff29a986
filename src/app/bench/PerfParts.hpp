#pragma once

#include <abalike/level/LevelDef.hpp>
#include <abalike/world/GameWorld.hpp>
#include <memory>
#include <string>
#include <vector>

class b2World;

namespace abalike::app
{

/// Summary of a set of step times (microseconds).
struct StepStats
{
    std::size_t count = 0;
    double medianUs = 0.0;
    double p95Us = 0.0;
    double meanUs = 0.0;
    double totalS = 0.0;
};

/// Median, 95th percentile, mean and total of step times given in seconds.
StepStats statsOf(std::vector<double> secondsPerStep);

/// One campaign level timed during its reference shot.
struct LevelPerf
{
    std::string file;
    std::string id;
    double angleDeg = 0.0;
    double speedMps = 0.0;
    std::string shotSource; ///< "level" (its reference_shot) or "search" (best of a quick search)
    int runs = 0;
    int stepsPerRun = 0;
    StepStats steps;             ///< every step of every run
    double realTimeFactor = 0.0; ///< simulated time / wall time of the shot, median over runs
    double atOnceFactor = 0.0;   ///< the same with the bird launched right after the settle step
};

/// Steps the campaign bench lets pass between the settle step and the shot: one second of aiming.
constexpr int kAimSteps = 60;

/// Times every level's reference shot (found by a quick search when the level has none).
std::vector<LevelPerf> measureCampaign(const std::vector<std::string>& levelPaths, int runs, bool quickSearch);

/// The 40-row pyramid stepped through GameWorld and through a plain b2World holding the same bodies.
struct PyramidPerf
{
    int rows = 0;
    int bodies = 0;
    int steps = 0;
    int runs = 0;
    bool allowSleep = true;
    StepStats ours;               ///< GameWorld::step, every step after the first of every run
    StepStats raw;                ///< b2World::Step with the same settings and bodies
    double firstStepOursMs = 0.0; ///< the settle step (WorldSettings::settleIterations), median over runs
    double firstStepRawMs = 0.0;
    double overheadRatio = 0.0;  ///< best of runs: min(our totals) / min(raw totals), interference filtered out
    double medianRunRatio = 0.0; ///< median over runs of (our total / raw total)
    bool sameFinalState = false; ///< both worlds ended with bit-identical body positions
};

PyramidPerf measurePyramid(int rows, int steps, int runs, bool allowSleep);

/// A plain b2World with the same bodies, fixtures and settings as `from`, created in the same order (Box2D lists
/// bodies and fixtures newest first), so that both worlds compute the same thing and only our layer differs.
std::unique_ptr<b2World> cloneWorld(const b2World& from, bool allowSleep);

/// One step of a plain b2World as `like` takes it: the same Box2D sub-steps (GameWorld::stackSubsteps) and
/// iterations, the settle iterations when `settle`; no contact listener, no rolling resistance.
void stepRawLike(b2World& world, const GameWorld& like, bool settle);

/// The 1 000-block wall (structureScenes "wall-20x50-mixed") at rest and while it collapses, stepped through our
/// world and through plain b2Worlds holding the same bodies: one with our settings, one with Box2D's defaults. Its
/// blocks are unbreakable here, so that all three worlds keep the same bodies to step.
struct WallPerf
{
    int bodies = 0;
    int substeps = 0; ///< our Box2D sub-steps per step
    double settleOursMs = 0.0;
    StepStats awakeOurs;    ///< at rest with sleep off: every body solved every step
    StepStats awakeRaw;     ///< plain Box2D, our iterations and sub-steps
    StepStats awakeDefault; ///< plain Box2D, 8/3 iterations, one step, no settle step
    StepStats restOurs;     ///< at rest, sleep on (as played): the wall falls asleep
    StepStats restRaw;
    StepStats restDefault;
    StepStats fallOurs; ///< after a blast at the wall's foot, sleep on
    StepStats fallRaw;
    StepStats fallDefault;
    int fallenOurs = 0; ///< blocks more than 0.5 m from where they were built at the end
};

WallPerf measureWall(int restSteps, int fallSteps);

/// One row of the iteration sweep: how far the stress scenes and campaign levels drift at rest, and the cost.
struct SettingsRow
{
    std::string label;
    WorldSettings settings;
    int substeps = 1;        ///< the step split in this many Box2D steps of dt / substeps
    double maxDriftMm = 0.0; ///< worst displacement of any body over all scenes
    std::string worstScene;
    int failingScenes = 0;         ///< scenes that moved more than 5 mm or took damage
    double usPerStep = 0.0;        ///< mean over all scenes' steps (sleep on unless said)
    double pyramidUsPerStep = 0.0; ///< mean over the 15-row pyramid's awake first second
};

std::vector<SettingsRow> sweepSettings(const std::vector<LevelDef>& scenes, double seconds);

/// The settle step of one scene with the default settings, and whether the scene then stands.
struct SettleRow
{
    std::string scene;
    int bodies = 0;
    int depth = 0;
    int substeps = 1; ///< Box2D sub-steps per step for its stacks
    int iterations = 0;
    double firstStepMs = 0.0;
    double maxDriftMm = 0.0; ///< over the rest check
    bool stands = false;
};

std::vector<SettleRow> settleTable(const std::vector<LevelDef>& scenes, double seconds);

/// CPU model and count, compiler: for the report header.
std::string machineDescription();

} // namespace abalike::app
