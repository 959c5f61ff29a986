#pragma once

#include <abalike/level/LevelDef.hpp>
#include <abalike/world/GameWorld.hpp>
#include <string>
#include <vector>

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
};

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

/// One row of the iteration sweep: how far the stress scenes and campaign levels drift at rest, and the cost.
struct SettingsRow
{
    std::string label;
    WorldSettings settings;
    int substeps = 1;        ///< the step split in this many Box2D steps of dt / substeps
    double maxDriftMm = 0.0; ///< worst displacement of any body over all scenes
    std::string worstScene;
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
    int iterations = 0;
    double firstStepMs = 0.0;
    double maxDriftMm = 0.0; ///< over the rest check
    bool stands = false;
};

std::vector<SettleRow> settleTable(const std::vector<LevelDef>& scenes, double seconds);

/// CPU model and count, compiler: for the report header.
std::string machineDescription();

} // namespace abalike::app
