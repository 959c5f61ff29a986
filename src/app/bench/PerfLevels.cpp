#include "bench/PerfParts.hpp"

#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>

namespace abalike::app
{

namespace
{

using Clock = std::chrono::steady_clock;

/// The first bird's best single shot on a coarse grid of angles and speeds (highest score, then most pigs).
ScriptedShot searchShot(const LevelDef& level, bool quick)
{
    const GameSession probe(level);
    const double top = probe.maxLaunchSpeed();
    const std::vector<double> angles = quick ? std::vector<double>{15, 30, 45, 60}
                                             : std::vector<double>{5, 10, 15, 20, 25, 30, 35, 40, 45, 50, 55, 60, 70};
    const std::vector<double> shares =
        quick ? std::vector<double>{0.6, 0.8, 1.0} : std::vector<double>{0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
    ScriptedShot best{45.0, top};
    int bestScore = -1;
    int bestPigs = -1;
    for (const double angle : angles)
        for (const double share : shares)
        {
            const ScriptedShot shot{angle, share * top};
            const auto session = simulateShots(level, {shot});
            const int score = session->score().total();
            const int pigs = session->score().pigsDefeated;
            if (score > bestScore || (score == bestScore && pigs > bestPigs))
            {
                best = shot;
                bestScore = score;
                bestPigs = pigs;
            }
        }
    return best;
}

} // namespace

std::vector<LevelPerf> measureCampaign(const std::vector<std::string>& levelPaths, int runs, bool quickSearch)
{
    std::vector<LevelPerf> results;
    for (const std::string& path : levelPaths)
    {
        const LevelDef level = loadLevel(path, Catalog::builtin());
        LevelPerf perf;
        perf.file = std::filesystem::path(path).filename().string();
        perf.id = level.id;
        perf.runs = runs;
        if (level.referenceShot)
        {
            perf.angleDeg = level.referenceShot->angleDeg;
            perf.speedMps = level.referenceShot->speedMps;
            perf.shotSource = "level";
        }
        else
        {
            const ScriptedShot shot = searchShot(level, quickSearch);
            perf.angleDeg = shot.angleDeg;
            perf.speedMps = shot.speedMps;
            perf.shotSource = "search";
        }

        std::vector<double> stepTimes;
        std::vector<double> factors;
        std::vector<double> atOnceFactors;
        for (int run = 0; run < runs; ++run)
        {
            // As played: the settle step belongs to loading the level, the next second to aiming (its structures
            // come to rest and Box2D puts them to sleep), then the shot is timed. Launched at once instead, every
            // body is still awake when the bird arrives, which no player sees (reported beside it).
            for (const int aimSteps : {kAimSteps, 0})
            {
                GameSession session(level);
                session.step();
                for (int i = 0; i < aimSteps; ++i)
                    session.step();
                session.launch(perf.angleDeg, perf.speedMps);
                const double simStart = session.simTime();
                double wall = 0.0;
                int steps = 0;
                while (session.phase() == Phase::Flying)
                {
                    const auto t0 = Clock::now();
                    session.step();
                    const double dt = std::chrono::duration<double>(Clock::now() - t0).count();
                    if (aimSteps > 0)
                        stepTimes.push_back(dt);
                    wall += dt;
                    ++steps;
                }
                const double factor = wall > 0.0 ? (session.simTime() - simStart) / wall : 0.0;
                if (aimSteps > 0)
                {
                    perf.stepsPerRun = steps;
                    factors.push_back(factor);
                }
                else
                    atOnceFactors.push_back(factor);
            }
        }
        perf.steps = statsOf(stepTimes);
        std::sort(factors.begin(), factors.end());
        perf.realTimeFactor = factors[factors.size() / 2];
        std::sort(atOnceFactors.begin(), atOnceFactors.end());
        perf.atOnceFactor = atOnceFactors[atOnceFactors.size() / 2];
        results.push_back(perf);
    }
    return results;
}

} // namespace abalike::app
