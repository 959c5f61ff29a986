#include "bench/PerfParts.hpp"

#include <abalike/world/StressScenes.hpp>
#include <algorithm>
#include <box2d/box2d.h>
#include <chrono>
#include <memory>
#include <vector>

namespace abalike::app
{

namespace
{

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since)
{
    return std::chrono::duration<double>(Clock::now() - since).count();
}

} // namespace

PyramidPerf measurePyramid(int rows, int steps, int runs, bool allowSleep)
{
    PyramidPerf perf;
    perf.rows = rows;
    perf.steps = steps;
    perf.runs = runs;
    perf.allowSleep = allowSleep;
    const LevelDef level = pyramidScene(rows);
    perf.bodies = static_cast<int>(level.blocks.size());
    WorldSettings settings;
    settings.allowSleep = allowSleep;
    settings.settleCache = false; // the settle step is timed and compared with raw Box2D's, bit for bit

    std::vector<double> ours;
    std::vector<double> raw;
    std::vector<double> ratios;
    std::vector<double> oursTotals;
    std::vector<double> rawTotals;
    std::vector<double> firstOurs;
    std::vector<double> firstRaw;
    perf.sameFinalState = true;
    for (int run = 0; run < runs; ++run)
    {
        // Alternate which goes first so that neither always runs on a warmer cache.
        GameWorld world(level, Catalog::builtin(), settings);
        const std::unique_ptr<b2World> plain = cloneWorld(world.box2d(), allowSleep);
        double oursTotal = 0.0;
        double rawTotal = 0.0;
        const auto runOurs = [&]
        {
            for (int i = 0; i < steps; ++i)
            {
                const auto t0 = Clock::now();
                world.step();
                const double dt = seconds(t0);
                (i == 0 ? firstOurs : ours).push_back(dt);
                oursTotal += i == 0 ? 0.0 : dt;
            }
        };
        const auto runRaw = [&]
        {
            for (int i = 0; i < steps; ++i)
            {
                const auto t0 = Clock::now();
                stepRawLike(*plain, world, i == 0);
                const double dt = seconds(t0);
                (i == 0 ? firstRaw : raw).push_back(dt);
                rawTotal += i == 0 ? 0.0 : dt;
            }
        };
        if (run % 2 == 0)
        {
            runOurs();
            runRaw();
        }
        else
        {
            runRaw();
            runOurs();
        }
        ratios.push_back(oursTotal / rawTotal);
        oursTotals.push_back(oursTotal);
        rawTotals.push_back(rawTotal);

        // Same bodies, same order, same steps: the positions must agree bit for bit.
        std::vector<b2Vec2> a;
        std::vector<b2Vec2> b;
        for (const b2Body* body = world.box2d().GetBodyList(); body != nullptr; body = body->GetNext())
            a.push_back(body->GetPosition());
        for (const b2Body* body = plain->GetBodyList(); body != nullptr; body = body->GetNext())
            b.push_back(body->GetPosition());
        perf.sameFinalState = perf.sameFinalState && a.size() == b.size() &&
                              std::equal(a.begin(), a.end(), b.begin(),
                                         [](const b2Vec2& p, const b2Vec2& q) { return p.x == q.x && p.y == q.y; });
    }
    perf.ours = statsOf(ours);
    perf.raw = statsOf(raw);
    std::sort(ratios.begin(), ratios.end());
    perf.medianRunRatio = ratios[ratios.size() / 2];
    perf.overheadRatio =
        *std::min_element(oursTotals.begin(), oursTotals.end()) / *std::min_element(rawTotals.begin(), rawTotals.end());
    perf.firstStepOursMs = 1e-3 * statsOf(firstOurs).medianUs;
    perf.firstStepRawMs = 1e-3 * statsOf(firstRaw).medianUs;
    return perf;
}

} // namespace abalike::app
