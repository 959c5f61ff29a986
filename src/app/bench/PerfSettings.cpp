#include "bench/PerfParts.hpp"

#include <abalike/world/RestCheck.hpp>
#include <abalike/world/StressScenes.hpp>
#include <chrono>
#include <cmath>

namespace abalike::app
{

namespace
{

using Clock = std::chrono::steady_clock;

/// Box2D with the iterations, settle step and sub-steps given and none of the issue-9 changes (square corners,
/// Box2D's own contact rule, no rolling resistance, no stack sub-steps).
WorldSettings plain(int velocity, int position, int settle, int substeps = 1)
{
    WorldSettings s;
    s.velocityIterations = velocity;
    s.positionIterations = position;
    s.settleIterations = settle;
    s.dtS = 1.0 / 60.0 / substeps; // sub-stepping: the same game step in several Box2D steps
    s.cornerChamferM = 0.0;
    s.contactGapM = -1.0;
    s.rollingResistance = false;
    s.maxStackSubsteps = 1;
    return s;
}

SettingsRow row(const std::string& label, const WorldSettings& settings, int substeps = 1)
{
    SettingsRow r;
    r.label = label;
    r.settings = settings;
    r.substeps = substeps;
    return r;
}

} // namespace

std::vector<SettingsRow> sweepSettings(const std::vector<LevelDef>& scenes, double seconds)
{
    constexpr int kAuto = WorldSettings::kAutoSettle;
    WorldSettings before = plain(8, 3, kAuto);
    WorldSettings chamfer = before;
    chamfer.cornerChamferM = WorldSettings{}.cornerChamferM;
    WorldSettings gap = chamfer;
    gap.contactGapM = WorldSettings{}.contactGapM;
    WorldSettings rolling = gap;
    rolling.rollingResistance = true;
    WorldSettings sleepless;
    sleepless.allowSleep = false;
    WorldSettings noChamfer;
    noChamfer.cornerChamferM = 0.0;
    std::vector<SettingsRow> rows{
        row("Box2D's recommendation, no settle step", plain(8, 3, 0)),
        row("more iterations", plain(20, 10, 0)),
        row("many more iterations", plain(50, 20, 0)),
        row("4 sub-steps (240 Hz)", plain(8, 3, 0, 4), 4),
        row("settle step of 2000", plain(8, 3, 2000)),
        row("before issue 9: automatic settle step", before),
        row("+ chamfered corners", chamfer),
        row("+ contacts only where designed surfaces touch", gap),
        row("+ rolling resistance", rolling),
        row("chosen: + stack sub-steps", WorldSettings{}),
        row("chosen, square corners", noChamfer),
        row("chosen, sleep off", sleepless),
    };
    const LevelDef pyramid = pyramidScene(15);
    for (SettingsRow& r : rows)
    {
        double wall = 0.0;
        for (const LevelDef& scene : scenes)
        {
            const auto t0 = Clock::now();
            const RestReport report = checkRest(scene, Catalog::builtin(), seconds, r.settings);
            wall += std::chrono::duration<double>(Clock::now() - t0).count();
            r.failingScenes += report.passed() ? 0 : 1;
            if (report.maxDisplacementM * 1000.0 >= r.maxDriftMm)
            {
                r.maxDriftMm = report.maxDisplacementM * 1000.0;
                r.worstScene = scene.id.empty() ? scene.title : scene.id;
            }
        }
        r.usPerStep = 1e6 * wall / (seconds * 60.0 * static_cast<double>(scenes.size()));

        // Solver cost while everything is awake: the 15-row pyramid's first second without sleeping.
        WorldSettings awake = r.settings;
        awake.allowSleep = false;
        GameWorld world(pyramid, Catalog::builtin(), awake);
        world.step();                      // the settle step is a one-off
        const int steps = 60 * r.substeps; // game steps of 1/60 s; stack sub-steps happen inside step()
        const auto t0 = Clock::now();
        for (int i = 0; i < steps; ++i)
            world.step();
        r.pyramidUsPerStep = 1e6 * std::chrono::duration<double>(Clock::now() - t0).count() / 60.0;
    }
    return rows;
}

std::vector<SettleRow> settleTable(const std::vector<LevelDef>& scenes, double seconds)
{
    std::vector<SettleRow> rows;
    for (const LevelDef& scene : scenes)
    {
        SettleRow r;
        r.scene = scene.id.empty() ? scene.title : scene.id;
        r.bodies = static_cast<int>(scene.blocks.size() + scene.pigs.size());
        WorldSettings timedSettle;
        timedSettle.settleCache = false; // the settle step is what this table times
        GameWorld world(scene, Catalog::builtin(), timedSettle);
        r.depth = world.stackDepth();
        r.substeps = world.stackSubsteps();
        r.iterations = world.settleIterations();
        const auto t0 = Clock::now();
        world.step();
        r.firstStepMs = 1e3 * std::chrono::duration<double>(Clock::now() - t0).count();
        const RestReport report = checkRest(scene, Catalog::builtin(), seconds);
        r.maxDriftMm = 1e3 * report.maxDisplacementM;
        r.stands = report.passed();
        rows.push_back(r);
    }
    return rows;
}

} // namespace abalike::app
