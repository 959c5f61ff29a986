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

SettingsRow row(const std::string& label, int velocity, int position, int settle, int substeps = 1, bool sleep = true)
{
    SettingsRow r;
    r.label = label;
    r.settings.velocityIterations = velocity;
    r.settings.positionIterations = position;
    r.settings.settleIterations = settle;
    r.settings.allowSleep = sleep;
    r.settings.dtS = 1.0 / 60.0 / substeps; // sub-stepping: the same game step in several Box2D steps
    r.substeps = substeps;
    return r;
}

} // namespace

std::vector<SettingsRow> sweepSettings(const std::vector<LevelDef>& scenes, double seconds)
{
    constexpr int kAuto = WorldSettings::kAutoSettle;
    std::vector<SettingsRow> rows{
        row("Box2D's recommendation, no settle step", 8, 3, 0),
        row("more iterations", 20, 10, 0),
        row("many more iterations", 50, 20, 0),
        row("4 sub-steps (240 Hz)", 8, 3, 0, 4),
        row("settle step of 500", 8, 3, 500),
        row("settle step of 2000", 8, 3, 2000),
        row("fewer iterations, automatic settle", 4, 2, kAuto),
        row("chosen: 8/3, automatic settle", 8, 3, kAuto),
        row("more iterations, automatic settle", 10, 4, kAuto),
        row("chosen, sleep off", 8, 3, kAuto, 1, false),
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
        world.step(); // the settle step is a one-off
        const int steps = 60 * r.substeps;
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
        GameWorld world(scene, Catalog::builtin());
        r.depth = world.stackDepth();
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
