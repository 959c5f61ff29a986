#include "bench/PerfParts.hpp"

#include <abalike/world/StressScenes.hpp>
#include <box2d/box2d.h>
#include <chrono>
#include <cmath>
#include <functional>

namespace abalike::app
{

namespace
{

using Clock = std::chrono::steady_clock;

/// A black bird's blast (250 N s at the centre, falling to 0 at 3 m) at the foot of the wall, on every dynamic body.
void blast(b2World& world, b2Vec2 centre)
{
    for (b2Body* b = world.GetBodyList(); b != nullptr; b = b->GetNext())
    {
        if (b->GetType() != b2_dynamicBody)
            continue;
        const b2Vec2 offset = b->GetWorldCenter() - centre;
        const float d = offset.Length();
        if (d >= 3.0f || d < 1e-6f)
            continue;
        b->ApplyLinearImpulseToCenter((250.0f * (1.0f - d / 3.0f) / d) * offset, true);
    }
}

/// Times `steps` calls of `step`; the times of the calls, in seconds.
std::vector<double> timed(int steps, const std::function<void()>& step)
{
    std::vector<double> times;
    times.reserve(static_cast<std::size_t>(steps));
    for (int i = 0; i < steps; ++i)
    {
        const auto t0 = Clock::now();
        step();
        times.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    }
    return times;
}

} // namespace

WallPerf measureWall(int restSteps, int fallSteps)
{
    LevelDef level;
    for (const StressScene& scene : structureScenes())
        if (scene.name == "wall-20x50-mixed")
            level = scene.level;
    WallPerf perf;
    perf.bodies = static_cast<int>(level.blocks.size() + level.pigs.size());

    GameWorld ours(level, Catalog::builtin());
    perf.substeps = ours.stackSubsteps();
    const std::unique_ptr<b2World> raw = cloneWorld(ours.box2d(), true);
    const std::unique_ptr<b2World> plain = cloneWorld(ours.box2d(), true);
    const float h = 1.0f / 60.0f;

    const auto t0 = Clock::now();
    ours.step();
    perf.settleOursMs = 1e3 * std::chrono::duration<double>(Clock::now() - t0).count();
    stepRawLike(*raw, ours, true);
    plain->Step(h, 8, 3);

    perf.restOurs = statsOf(timed(restSteps, [&] { ours.step(); }));
    perf.restRaw = statsOf(timed(restSteps, [&] { stepRawLike(*raw, ours, false); }));
    perf.restDefault = statsOf(timed(restSteps, [&] { plain->Step(h, 8, 3); }));

    const b2Vec2 foot(25.0f, 0.5f); // the middle of the wall's bottom row
    blast(ours.box2d(), foot);
    blast(*raw, foot);
    blast(*plain, foot);
    perf.fallOurs = statsOf(timed(fallSteps, [&] { ours.step(); }));
    perf.fallRaw = statsOf(timed(fallSteps, [&] { stepRawLike(*raw, ours, false); }));
    perf.fallDefault = statsOf(timed(fallSteps, [&] { plain->Step(h, 8, 3); }));
    for (const Entity& e : ours.entities())
    {
        if (e.kind != EntityKind::Block)
            continue;
        const BlockDef& b = level.blocks[static_cast<std::size_t>(e.defIndex)];
        if (!e.alive || std::hypot(e.body->GetPosition().x - b.x, e.body->GetPosition().y - b.y) > 0.5)
            ++perf.fallenOurs;
    }
    return perf;
}

} // namespace abalike::app
