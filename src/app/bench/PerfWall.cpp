#include "bench/PerfParts.hpp"

#include <abalike/world/StressScenes.hpp>
#include <box2d/box2d.h>
#include <chrono>
#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>

namespace abalike::embedded
{
extern const char* const kCatalogJson; // assets/catalog.json, compiled into the core
}

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
    // Our world removes what breaks; raw Box2D cannot. Unbreakable blocks keep the three worlds' work the same.
    nlohmann::json root = nlohmann::json::parse(embedded::kCatalogJson);
    for (nlohmann::json& material : root["materials"])
        material["strength_ns"] = 1e9;
    const Catalog catalog = Catalog::fromJson(root.dump());
    WallPerf perf;
    perf.bodies = static_cast<int>(level.blocks.size() + level.pigs.size());
    const float h = 1.0f / 60.0f;

    // Three worlds with the same bodies, each past its first step.
    struct Worlds
    {
        std::unique_ptr<GameWorld> ours;
        std::unique_ptr<b2World> raw;
        std::unique_ptr<b2World> plain;
    };
    const auto build = [&](bool sleep)
    {
        WorldSettings settings;
        settings.allowSleep = sleep;
        settings.settleCache = false; // the settle step is timed and raw Box2D repeats it
        Worlds w{std::make_unique<GameWorld>(level, catalog, settings), nullptr, nullptr};
        w.raw = cloneWorld(w.ours->box2d(), sleep);
        w.plain = cloneWorld(w.ours->box2d(), sleep);
        const auto t0 = Clock::now();
        w.ours->step();
        perf.settleOursMs = 1e3 * std::chrono::duration<double>(Clock::now() - t0).count();
        stepRawLike(*w.raw, *w.ours, true);
        w.plain->Step(h, 8, 3);
        return w;
    };

    {
        Worlds awake = build(false);
        perf.substeps = awake.ours->stackSubsteps();
        perf.awakeOurs = statsOf(timed(restSteps / 2, [&] { awake.ours->step(); }));
        perf.awakeRaw = statsOf(timed(restSteps / 2, [&] { stepRawLike(*awake.raw, *awake.ours, false); }));
        perf.awakeDefault = statsOf(timed(restSteps / 2, [&] { awake.plain->Step(h, 8, 3); }));
    }

    Worlds w = build(true);
    perf.restOurs = statsOf(timed(restSteps, [&] { w.ours->step(); }));
    perf.restRaw = statsOf(timed(restSteps, [&] { stepRawLike(*w.raw, *w.ours, false); }));
    perf.restDefault = statsOf(timed(restSteps, [&] { w.plain->Step(h, 8, 3); }));

    const b2Vec2 foot(25.0f, 0.5f); // the middle of the wall's bottom row
    blast(w.ours->box2d(), foot);
    blast(*w.raw, foot);
    blast(*w.plain, foot);
    perf.fallOurs = statsOf(timed(fallSteps, [&] { w.ours->step(); }));
    perf.fallRaw = statsOf(timed(fallSteps, [&] { stepRawLike(*w.raw, *w.ours, false); }));
    perf.fallDefault = statsOf(timed(fallSteps, [&] { w.plain->Step(h, 8, 3); }));
    for (const Entity& e : w.ours->entities())
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
