#include "bench/BenchSuite.hpp"
#include "bench/PerfParts.hpp"
#include "render/TextFormat.hpp"
#include "shell/DataPaths.hpp"

#include <abalike/level/LevelIO.hpp>
#include <abalike/world/StressScenes.hpp>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace abalike::app
{

namespace
{

constexpr double kMinRealTimeFactor = 1000.0; ///< headless speed target per campaign level
constexpr double kMaxOverhead = 1.2;          ///< our world's step time over raw Box2D's

/// How much work each part does: the full run for figures, the quick one as a smoke test.
struct PerfPlan
{
    int levelRuns = 5;
    int pyramidRows = 40;   ///< 820 boxes
    int pyramidSteps = 600; ///< 10 s of game time
    int pyramidRuns = 5;
    int wallRestSteps = 600; ///< the 1 000-block wall: 10 s at rest, then 10 s after a blast
    int wallFallSteps = 600;
    double sweepSeconds = 30.0;
    double settleSeconds = 10.0;
};

std::string pyramidLabel(const PyramidPerf& p)
{
    return p.allowSleep ? "sleep on (as played)" : "sleep off (every body solved every step)";
}

} // namespace

int runPerfBench(const BenchOptions& options)
{
    PerfPlan plan;
    if (options.quick)
        plan = {1, 15, 20, 1, 10, 10, 2.0, 2.0}; // every part runs; the settle steps of big scenes dominate

    std::vector<std::string> levelPaths;
    std::vector<LevelDef> sweepScenes;
    for (const StressScene& scene : stressScenes())
        sweepScenes.push_back(scene.level);
    // Walls, mixed towers, ledges (issue 9); a quick run leaves out the 1 000-block wall (its settle step alone
    // takes seconds), which the full run and the wall section below time.
    for (const StressScene& scene : structureScenes())
        if (!options.quick || scene.level.blocks.size() < 1000)
        {
            sweepScenes.push_back(scene.level);
            sweepScenes.back().id = scene.name;
        }
    try
    {
        levelPaths = loadCampaign(campaignManifest());
        for (const std::string& path : levelPaths)
            sweepScenes.push_back(loadLevel(path, Catalog::builtin()));
    }
    catch (const LevelLoadError& e)
    {
        std::cerr << "abalike: error: bench perf: " << e.what() << '\n';
        return 1;
    }

    std::cout << "bench perf" << (options.quick ? " --quick" : "") << ": " << machineDescription() << '\n';
    const std::vector<LevelPerf> levels = measureCampaign(levelPaths, plan.levelRuns, options.quick);
    const std::vector<PyramidPerf> pyramids{
        measurePyramid(plan.pyramidRows, plan.pyramidSteps, plan.pyramidRuns, true),
        measurePyramid(plan.pyramidRows, plan.pyramidSteps, plan.pyramidRuns, false)};
    if (options.quick)
    {
        // A smoke test runs every part on a few scenes of each kind: two stress scenes, two structures, two levels.
        const std::size_t stress = stressScenes().size();
        const std::size_t structures = structureScenes().size() - 1;
        std::vector<LevelDef> few;
        for (std::size_t i :
             {std::size_t{0}, std::size_t{1}, stress, stress + 1, stress + structures, stress + structures + 1})
            if (i < sweepScenes.size())
                few.push_back(sweepScenes[i]);
        sweepScenes = few;
    }
    std::vector<LevelDef> settleScenes = sweepScenes;
    for (int rows : {20, 30, 40})
        if (rows <= plan.pyramidRows)
            settleScenes.push_back(pyramidScene(rows));
    if (!options.quick)
        sweepScenes.push_back(pyramidScene(plan.pyramidRows));
    const WallPerf wall = measureWall(plan.wallRestSteps, plan.wallFallSteps);
    const std::vector<SettingsRow> sweep = sweepSettings(sweepScenes, plan.sweepSeconds);
    const std::vector<SettleRow> settle = settleTable(settleScenes, plan.settleSeconds);

    bool pass = true;
    std::ostringstream md;
    md << "# World performance (`abalike bench perf" << (options.quick ? " --quick" : "") << "`)\n\n"
       << "Machine: " << machineDescription() << ".\n\n";

    md << "## Campaign levels during their reference shot\n\n"
       << "Each level is loaded, its settle step taken and " << kAimSteps
       << " steps (a second of aiming, in which its structures come to rest and fall asleep) stepped, then its "
          "reference shot (the level's `reference_shot`, or the best of a quick search) is fired and every "
          "`GameSession::step()` until the shot is over is timed; "
       << plan.levelRuns << " run(s) per level. Target: headless speed >= " << kMinRealTimeFactor
       << "x real time. Beside it, the speed with the bird launched right after the settle step, while every body "
          "is still awake (no player shoots that fast; not a target).\n\n"
       << "| Level | Shot (deg, m/s) | Shot from | Steps | Median step (us) | p95 step (us) | Speed (x real time) | "
          "Target met | Launched at once (x real time) |\n|---|---|---|---:|---:|---:|---:|---|---:|\n";
    for (const LevelPerf& l : levels)
    {
        const bool ok = l.realTimeFactor >= kMinRealTimeFactor;
        pass = pass && ok;
        md << "| " << l.file << " | " << formatFixed(l.angleDeg, 1) << ", " << formatFixed(l.speedMps, 2) << " | "
           << l.shotSource << " | " << l.stepsPerRun << " | " << formatFixed(l.steps.medianUs, 1) << " | "
           << formatFixed(l.steps.p95Us, 1) << " | " << formatFixed(l.realTimeFactor, 0) << " | " << (ok ? "yes" : "NO")
           << " | " << formatFixed(l.atOnceFactor, 0) << " |\n";
    }

    md << "\n## " << plan.pyramidRows << "-row pyramid (" << pyramids[0].bodies
       << " boxes): our world against raw Box2D\n\n"
       << "The same bodies, fixtures and settings (8 velocity and 3 position iterations, the automatic settle step "
          "first, the same Box2D sub-steps per step: "
       << GameWorld(pyramidScene(plan.pyramidRows), Catalog::builtin()).stackSubsteps()
       << " for a stack 40 deep) stepped through `GameWorld::step()` and "
       << "through a plain `b2World::Step()` with no listener; " << plan.pyramidSteps << " steps, " << plan.pyramidRuns
       << " run(s) each, alternating which goes first. The first (settle) step is reported "
       << "apart. Overhead: the best run of ours over the best run of raw Box2D (the median of the per-run ratios "
          "beside it); a ratio below 1 is noise from other processes. Target: overhead <= "
       << kMaxOverhead << ".\n\n"
       << "| Case | Ours median (us) | Ours p95 (us) | Raw median (us) | Raw p95 (us) | Settle step ours / raw (ms) | "
          "Overhead (best / median of runs) | Same final state | Target met |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---|---|\n";
    for (const PyramidPerf& p : pyramids)
    {
        const bool ok = p.overheadRatio <= kMaxOverhead;
        pass = pass && ok;
        md << "| " << pyramidLabel(p) << " | " << formatFixed(p.ours.medianUs, 1) << " | "
           << formatFixed(p.ours.p95Us, 1) << " | " << formatFixed(p.raw.medianUs, 1) << " | "
           << formatFixed(p.raw.p95Us, 1) << " | " << formatFixed(p.firstStepOursMs, 1) << " / "
           << formatFixed(p.firstStepRawMs, 1) << " | " << formatFixed(p.overheadRatio, 3) << " / "
           << formatFixed(p.medianRunRatio, 3) << " | " << (p.sameFinalState ? "yes, bit for bit" : "no") << " | "
           << (ok ? "yes" : "NO") << " |\n";
    }

    const auto stats = [](const StepStats& st)
    {
        return formatFixed(st.medianUs, 1) + " / " + formatFixed(st.meanUs, 1);
    };
    md << "\n## The 1 000-block wall: our world against raw Box2D\n\n"
       << "`wall-20x50-mixed` (" << wall.bodies
       << " bodies: 20 x 50 bricks of 0.5 x 0.25 m, wood, ice and stone in turn, a pig on top), its blocks made "
          "unbreakable so that every world keeps the same bodies. Three worlds with the same bodies: ours (8/3 "
          "iterations, "
       << wall.substeps
       << " Box2D sub-steps per step for a stack 51 deep, settle step, contact rule, rolling resistance; the settle "
          "step took "
       << formatFixed(wall.settleOursMs, 0)
       << " ms), a plain `b2World` with the same iterations, sub-steps and settle step, and a plain `b2World` with "
          "Box2D's defaults (8/3, one step, no settle step). Stepped "
       << plan.wallRestSteps / 2
       << " times at rest with sleep off (every body solved every step), then, in new worlds, " << plan.wallRestSteps
       << " times at rest with sleep on (as played) and " << plan.wallFallSteps
       << " times after a black bird's blast (250 N s within 3 m) at the foot of its middle, after which "
       << wall.fallenOurs
       << " blocks lie more than 0.5 m from where they were built in our world. Microseconds per game step (1/60 s), "
          "median / mean. The dynamics differ (without our changes the raw worlds do not stand still, so they do "
          "not fall asleep), so the sleep-off row is the like-for-like cost.\n\n"
       << "| Phase | Ours | Raw Box2D, our settings | Raw Box2D, its defaults | Ours / raw, our settings (mean) |\n"
       << "|---|---:|---:|---:|---:|\n";
    const auto wallRow = [&](const char* phase, const StepStats& o, const StepStats& r, const StepStats& d)
    {
        md << "| " << phase << " | " << stats(o) << " | " << stats(r) << " | " << stats(d) << " | "
           << formatFixed(o.meanUs / r.meanUs, 2) << " |\n";
    };
    wallRow("at rest, sleep off", wall.awakeOurs, wall.awakeRaw, wall.awakeDefault);
    wallRow("at rest, sleep on (as played)", wall.restOurs, wall.restRaw, wall.restDefault);
    wallRow("collapsing after the blast", wall.fallOurs, wall.fallRaw, wall.fallDefault);

    md << "\n## Box2D settings: drift at rest against cost\n\n";
    if (options.quick)
        md << "Two stress scenes, two structure scenes and two campaign levels (a quick run)";
    else
        md << "Every stress scene (" << stressScenes().size() << "), structure scene (" << structureScenes().size()
           << "), campaign level (" << levelPaths.size() << ") and the 40-row pyramid";
    md << " left alone for " << plan.sweepSeconds
       << " s through `checkRest()`; a scene fails when a body moves more than 5 mm or takes damage; drift is the "
          "largest move of any "
       << "corner of any body from where it was designed. Cost: wall time per game step (1/60 s) of those checks "
          "(sleep on, so mostly resting bodies), and per game step of the 15-row pyramid kept awake.\n\n"
       << "| Settings | Velocity / position iterations | Settle step | Sub-steps | Sleep | Scenes failing | Max "
          "drift (mm) | Worst scene | us per step at rest | us per step, pyramid awake |\n"
       << "|---|---:|---:|---:|---|---:|---:|---|---:|---:|\n";
    for (const SettingsRow& r : sweep)
        md << "| " << r.label << " | " << r.settings.velocityIterations << " / " << r.settings.positionIterations
           << " | "
           << (r.settings.settleIterations == WorldSettings::kAutoSettle ? std::string("auto")
                                                                         : std::to_string(r.settings.settleIterations))
           << " | " << (r.settings.maxStackSubsteps > 1 ? "by depth" : std::to_string(r.substeps)) << " | "
           << (r.settings.allowSleep ? "on" : "off") << " | " << r.failingScenes << " | "
           << formatFixed(r.maxDriftMm, 3) << " | " << r.worstScene << " | " << formatFixed(r.usPerStep, 1) << " | "
           << formatFixed(r.pyramidUsPerStep, 1) << " |\n";

    md << "\n## The automatic settle step and stack sub-steps per scene\n\n"
       << "Depth: the most bodies resting on each other; sub-steps: Box2D steps per game step for the stacks, "
          "ceil(depth / 5), at most 4; settle iterations: 5 x depth^2, at least 2000, at most 10 000, in each "
          "sub-step of the first step; then the rest check of "
       << plan.settleSeconds << " s with the default settings.\n\n"
       << "| Scene | Bodies | Depth | Sub-steps | Settle iterations | Settle step (ms) | Max drift (mm) | Stands |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---|\n";
    for (const SettleRow& r : settle)
        md << "| " << r.scene << " | " << r.bodies << " | " << r.depth << " | " << r.substeps << " | " << r.iterations
           << " | " << formatFixed(r.firstStepMs, 1) << " | " << formatFixed(r.maxDriftMm, 3) << " | "
           << (r.stands ? "yes" : "NO") << " |\n";
    md << "\nResult: " << (pass ? "every target met" : "a target was MISSED") << ".\n";

    const std::filesystem::path out(options.outDir);
    std::ofstream csv(out / "perf.csv");
    csv << "section,case,runs,steps,median_us,p95_us,mean_us,value,target,pass\n";
    const auto wallCsv = [&](const std::string& name, int steps, const StepStats& st)
    {
        csv << "wall," << name << ",1," << steps << ',' << st.medianUs << ',' << st.p95Us << ',' << st.meanUs
            << ",,,\n";
    };
    wallCsv("awake-ours", plan.wallRestSteps / 2, wall.awakeOurs);
    wallCsv("awake-raw", plan.wallRestSteps / 2, wall.awakeRaw);
    wallCsv("awake-default", plan.wallRestSteps / 2, wall.awakeDefault);
    wallCsv("rest-ours", plan.wallRestSteps, wall.restOurs);
    wallCsv("rest-raw", plan.wallRestSteps, wall.restRaw);
    wallCsv("rest-default", plan.wallRestSteps, wall.restDefault);
    wallCsv("collapse-ours", plan.wallFallSteps, wall.fallOurs);
    wallCsv("collapse-raw", plan.wallFallSteps, wall.fallRaw);
    wallCsv("collapse-default", plan.wallFallSteps, wall.fallDefault);
    for (const LevelPerf& l : levels)
        csv << "level," << l.file << ',' << l.runs << ',' << l.stepsPerRun << ',' << l.steps.medianUs << ','
            << l.steps.p95Us << ',' << l.steps.meanUs << ',' << l.realTimeFactor << ",>=" << kMinRealTimeFactor << ','
            << (l.realTimeFactor >= kMinRealTimeFactor) << '\n';
    for (const PyramidPerf& p : pyramids)
    {
        const std::string sleep = p.allowSleep ? "sleep-on" : "sleep-off";
        csv << "pyramid-ours," << sleep << ',' << p.runs << ',' << p.steps << ',' << p.ours.medianUs << ','
            << p.ours.p95Us << ',' << p.ours.meanUs << ',' << p.overheadRatio << ",<=" << kMaxOverhead << ','
            << (p.overheadRatio <= kMaxOverhead) << '\n';
        csv << "pyramid-raw," << sleep << ',' << p.runs << ',' << p.steps << ',' << p.raw.medianUs << ',' << p.raw.p95Us
            << ',' << p.raw.meanUs << ",,,\n";
    }
    for (const SettleRow& r : settle)
        csv << "settle," << r.scene << ",1,1," << 1e3 * r.firstStepMs << ",,," << r.maxDriftMm << ",<=5," << r.stands
            << '\n';
    for (const SettingsRow& r : sweep)
        csv << "settings,\"" << r.label << "\",1," << static_cast<int>(plan.sweepSeconds * 60) << ",,"
            << "," << r.usPerStep << ',' << r.maxDriftMm << ",<=5," << (r.maxDriftMm <= 5.0) << '\n';
    std::ofstream(out / "perf.md") << md.str();
    std::cout << md.str();
    if (!csv)
    {
        std::cerr << "abalike: error: bench perf: cannot write perf.csv or perf.md in " << options.outDir << '\n';
        return 1;
    }
    // A quick run is a smoke test: a handful of timings on a busy machine prove nothing either way.
    return pass || options.quick ? 0 : 1;
}

} // namespace abalike::app
