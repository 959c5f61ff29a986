#include "cli/Arguments.hpp"
#include "cli/Commands.hpp"
#include "cli/Print.hpp"
#include "cli/UsageError.hpp"

#include <abalike/teach/Rk4Walkthrough.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace abalike::app
{

namespace
{

struct WalkthroughArgs
{
    std::string x0 = "0", y0 = "0", vx, vy, dt, t0 = "0";
    FlightModelArgs model;
    bool json = false;
};

nlohmann::ordered_json stateJson(const FlightState& s)
{
    return nlohmann::ordered_json::array({s.position.x, s.position.y, s.velocity.x, s.velocity.y});
}

/// One row of the readable table: a label, four numbers and a note.
void printRow(const char* label, const FlightState& values, const std::string& note)
{
    print("%-8s %14.10g %14.10g %14.10g %14.10g  %s\n", label, values.position.x, values.position.y, values.velocity.x,
          values.velocity.y, note.c_str());
}

void printTable(const Rk4Walkthrough& walk)
{
    const double h = walk.dtS;
    print("One RK4 step from t0 = %g s with dt = %g s. The k are slopes f(t, state) = d(x, y, vx, vy)/dt, not "
          "increments.\n\n",
          walk.t0S, h);
    print("%-8s %14s %14s %14s %14s  %s\n", "", "x", "y", "vx", "vy", "");
    printRow("state", walk.state, "(m, m, m/s, m/s)");
    static const char* const kNames[] = {"k1", "k2", "k3", "k4"};
    static const char* const kWhere[] = {"f(t0, state)", "f(t0 + dt/2, state + dt/2 k1)",
                                         "f(t0 + dt/2, state + dt/2 k2)", "f(t0 + dt, state + dt k3)"};
    for (std::size_t i = 0; i < walk.stages.size(); ++i)
        printRow(kNames[i], walk.stages[i].slope, std::string(kWhere[i]) + "  (m/s, m/s, m/s^2, m/s^2)");
    printRow("average", walk.averageSlope, "(k1 + 2 k2 + 2 k3 + k4) / 6");
    printRow("next", walk.next, "state + dt * average, at t0 + dt");
    if (walk.exact)
    {
        printRow("exact", *walk.exact, "closed form at t0 + dt");
        const FlightState error{walk.next.position - walk.exact->position, walk.next.velocity - walk.exact->velocity};
        printRow("error", error, "next - exact");
    }
    else
        print("%-8s no closed form with quadratic drag or gusts\n", "exact");
    print("\nEach k is evaluated at the point printed here:\n");
    for (std::size_t i = 0; i < walk.stages.size(); ++i)
        printRow(kNames[i], walk.stages[i].at, "at t = " + std::to_string(walk.stages[i].tS) + " s");
}

int runWalkthrough(const WalkthroughArgs& a)
{
    const FlightModel model = parseFlightModel(a.model);
    const FlightState state{{parseFinite(a.x0, "--x0"), parseFinite(a.y0, "--y0")},
                            {parseFinite(a.vx, "--vx"), parseFinite(a.vy, "--vy")}};
    const double dt = a.dt.empty() ? 1.0 / 60.0 : parseFinite(a.dt, "--dt");
    if (dt <= 0.0)
        throw UsageError("--dt: must be > 0 s, got " + a.dt);
    const double t0 = parseFinite(a.t0, "--t0");
    Rk4Walkthrough walk;
    try
    {
        walk = walkRk4Step(model, t0, state, dt);
    }
    catch (const std::invalid_argument& e)
    {
        throw UsageError(e.what());
    }
    // Every input was finite, but the forces or the step can still overflow a double: refuse rather than print inf.
    bool ok = isFinite(walk.next) && isFinite(walk.averageSlope) && (!walk.exact || isFinite(*walk.exact));
    for (const Rk4Stage& stage : walk.stages)
        ok = ok && isFinite(stage.slope) && isFinite(stage.at);
    if (!ok)
        throw UsageError("the forces or the step overflow a double at this state; use a smaller speed, drag or step");
    if (!a.json)
    {
        printTable(walk);
        return 0;
    }
    nlohmann::ordered_json out;
    out["stepper"] = "rk4";
    out["dt"] = walk.dtS;
    out["state"] = stateJson(walk.state);
    out["k1"] = stateJson(walk.stages[0].slope);
    out["k2"] = stateJson(walk.stages[1].slope);
    out["k3"] = stateJson(walk.stages[2].slope);
    out["k4"] = stateJson(walk.stages[3].slope);
    out["next"] = stateJson(walk.next);
    out["exact"] = walk.exact ? stateJson(*walk.exact) : nlohmann::ordered_json(nullptr);
    std::cout << out.dump() << '\n';
    return 0;
}

} // namespace

CommandRunner addWalkthroughCommand(CLI::App& app)
{
    auto args = std::make_shared<WalkthroughArgs>();
    CLI::App* cmd = app.add_subcommand("walkthrough", "Show one RK4 step: its four slopes k1..k4 and the result");
    cmd->add_option("--x0", args->x0, "x in m (default 0)");
    cmd->add_option("--y0", args->y0, "y in m (default 0)");
    cmd->add_option("--vx", args->vx, "vx in m/s")->required();
    cmd->add_option("--vy", args->vy, "vy in m/s")->required();
    cmd->add_option("--dt", args->dt, "the step in s (default 1/60, the physics step)");
    cmd->add_option("--t0", args->t0, "time of the state in s, for gusts (default 0)");
    addFlightModelOptions(*cmd, args->model);
    cmd->add_flag("--json", args->json, "print one JSON object");
    return [args]
    {
        return runWalkthrough(*args);
    };
}

} // namespace abalike::app
