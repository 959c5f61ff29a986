#include "cli/Arguments.hpp"
#include "cli/Commands.hpp"
#include "cli/UsageError.hpp"

#include <abalike/flight/Prediction.hpp>
#include <abalike/level/SlingshotBand.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <vector>

namespace abalike::app
{

namespace
{

/// A prediction writes one path point per step; past this the output is no longer useful to anyone.
constexpr double kMaxSteps = 2.0e6;

struct PredictArgs
{
    std::string angle, speed, x0 = "0", y0 = "0", dt, untilT, maxT = "60";
    std::string pull, maxForce = "8100", maxPull = "2", bandMass = "14"; ///< a launch by a band instead of a speed
    std::string stepper = "rk4", tol = "1e-9";
    FlightModelArgs model;
    bool json = false;
    bool noGuard = false;
};

/// With --pull: the launch the slingshot's band gives a bird of this mass (docs/slingshot.md). There is no world
/// here, so no launch-speed cap.
std::optional<BandPull> bandLaunch(const PredictArgs& a, double massKg)
{
    if (a.pull.empty())
        return std::nullopt;
    BandDef sling;
    sling.maxForceN = parseFinite(a.maxForce, "--max-force");
    sling.maxPullM = parseFinite(a.maxPull, "--max-pull");
    sling.bandMassKg = parseFinite(a.bandMass, "--band-mass");
    const double pull = parseFinite(a.pull, "--pull");
    if (sling.maxForceN <= 0.0)
        throw UsageError("--max-force: must be > 0 N, got " + a.maxForce);
    if (sling.maxPullM <= 0.0)
        throw UsageError("--max-pull: must be > 0 m, got " + a.maxPull);
    if (sling.bandMassKg < 0.0)
        throw UsageError("--band-mass: must be >= 0 kg, got " + a.bandMass);
    if (pull < 0.0 || pull > sling.maxPullM)
        throw UsageError("--pull: must be between 0 and the full pull " + a.maxPull + " m, got " + a.pull);
    const SlingshotBand band(sling, massKg, std::numeric_limits<double>::infinity());
    return band.atFraction(pull / sling.maxPullM);
}

int runPredict(const PredictArgs& a)
{
    const FlightModel model = parseFlightModel(a.model);

    IntegratorSettings settings;
    const auto stepper = parseStepper(a.stepper);
    if (!stepper)
        throw UsageError("--stepper: unknown stepper \"" + a.stepper +
                         "\" (expected euler, semi-implicit-euler, rk4, dopri5 or analytic)");
    settings.stepper = *stepper;
    settings.dtS = a.dt.empty() ? 1.0 / 60.0 : parseFinite(a.dt, "--dt");
    settings.tolerance = parseFinite(a.tol, "--tol");
    settings.guardStiffness = !a.noGuard;
    if (settings.dtS <= 0.0)
        throw UsageError("--dt: must be > 0 s, got " + a.dt);
    if (settings.tolerance < 1e-14)
        throw UsageError("--tol: must be >= 1e-14 (finer is below double precision), got " + a.tol);

    const double angle = parseFinite(a.angle, "--angle");
    const std::optional<BandPull> band = bandLaunch(a, model.massKg);
    if (!band && a.speed.empty())
        throw UsageError("give the launch as --speed M/S or as --pull M (the slingshot's band)");
    const double speed = band ? band->speedMps : parseFinite(a.speed, "--speed");
    if (speed < 0.0)
        throw UsageError("--speed: must be >= 0 m/s, got " + a.speed);
    const double x0 = parseFinite(a.x0, "--x0");
    const double y0 = parseFinite(a.y0, "--y0");

    PredictionLimits limits;
    limits.maxTimeS = parseFinite(a.maxT, "--max-t");
    if (limits.maxTimeS <= 0.0)
        throw UsageError("--max-t: must be > 0 s, got " + a.maxT);
    if (!a.untilT.empty())
    {
        limits.untilTimeS = parseFinite(a.untilT, "--until-t");
        if (*limits.untilTimeS <= 0.0)
            throw UsageError("--until-t: must be > 0 s, got " + a.untilT);
    }
    limits.stopOnLanding = true;
    const double endTime = limits.untilTimeS ? *limits.untilTimeS : limits.maxTimeS;
    if (endTime / settings.dtS > kMaxSteps)
        throw UsageError("--dt " + std::to_string(settings.dtS) + " over " + std::to_string(endTime) +
                         " s is more than 2 million steps; use a larger --dt or a shorter flight");

    PredictedFlight flight;
    try
    {
        flight = predictFlight(model, settings, launchState(x0, y0, speed, angle), limits);
    }
    catch (const std::invalid_argument& e)
    {
        throw UsageError(e.what());
    }
    const PathPoint& last = flight.path.back();
    // Without the guard, blowing up is the behaviour being shown: report it. With the guard, only inputs beyond
    // what a double can carry diverge, and that is an error.
    const bool diverged = flight.end == FlightEnd::Diverged;
    if (diverged && settings.guardStiffness)
        throw UsageError("the flight left the range of a double at t = " + std::to_string(flight.path.back().timeS) +
                         " s (the forces overflow: use a smaller speed, drag or a larger mass)");
    const bool landed = flight.end == FlightEnd::Landed;

    if (!a.json)
    {
        std::cout << "stepper " << stepperName(settings.stepper) << ", dt " << settings.dtS << " s, " << flight.steps
                  << " steps, " << flight.rhsEvaluations << " evaluations, stiffness guard "
                  << guardActionName(flight.guard) << " (" << flight.substeps << " sub-steps)\n"
                  << (landed ? "landed" : "stopped") << " after " << last.timeS << " s at x = " << last.state.position.x
                  << " m (range " << last.state.position.x - x0 << " m), highest point " << flight.maxHeightM << " m\n";
        return 0;
    }

    nlohmann::ordered_json out;
    if (band)
        out["launch"] = {{"pull_m", band->pullM},
                         {"force_n", band->forceN},
                         {"energy_j", band->energyJ},
                         {"bird_energy_j", band->birdEnergyJ},
                         {"band_energy_j", band->bandEnergyJ},
                         {"speed_mps", band->speedMps}};
    out["stepper"] = stepperName(settings.stepper);
    out["dt"] = settings.dtS;
    out["steps"] = flight.steps;
    out["substeps"] = flight.substeps;
    out["guard"] = guardActionName(flight.guard);
    out["rhs_evaluations"] = flight.rhsEvaluations;
    out["terms"] = termNames(activeTerms(model));
    out["landed"] = landed;
    out["diverged"] = diverged; // the path stops at the last finite state
    out["range_m"] = last.state.position.x - x0;
    out["flight_time_s"] = last.timeS;
    out["max_height_m"] = flight.maxHeightM;
    out["max_stiffness_ratio"] = flight.maxStiffnessRatio;
    out["final"] = {{"t", last.timeS},
                    {"x", last.state.position.x},
                    {"y", last.state.position.y},
                    {"vx", last.state.velocity.x},
                    {"vy", last.state.velocity.y}};
    nlohmann::ordered_json path = nlohmann::ordered_json::array();
    for (const PathPoint& p : flight.path)
        path.push_back({p.timeS, p.state.position.x, p.state.position.y, p.state.velocity.x, p.state.velocity.y});
    out["path"] = std::move(path);
    std::cout << out.dump() << '\n';
    return 0;
}

} // namespace

CommandRunner addPredictCommand(CLI::App& app)
{
    auto args = std::make_shared<PredictArgs>();
    CLI::App* cmd = app.add_subcommand("predict", "Integrate a flight (no level) and print where it lands");
    cmd->add_option("--angle", args->angle, "launch angle in degrees above horizontal")->required();
    auto* speed = cmd->add_option("--speed", args->speed, "launch speed in m/s (or --pull)");
    auto* pull = cmd->add_option("--pull", args->pull,
                                 "launch by the slingshot's band drawn back this far (m): v0 = sqrt(2E/(m + m_b)) "
                                 "with E = 1/2 F x (instead of --speed; --mass is the bird's)");
    speed->excludes(pull);
    cmd->add_option("--max-force", args->maxForce, "with --pull: the band's force at full pull in N (default 8100)")
        ->needs(pull);
    cmd->add_option("--band-mass", args->bandMass,
                    "with --pull: the band's mass moving with the bird in kg (default 14; 0: a massless band)")
        ->needs(pull);
    cmd->add_option("--max-pull", args->maxPull, "with --pull: the band's full pull in m (default 2)")->needs(pull);
    cmd->add_option("--x0", args->x0, "launch x in m (default 0)");
    cmd->add_option("--y0", args->y0,
                    "launch y in m (default 0); the flight ends when it comes back down to y0, not at y = 0");
    addFlightModelOptions(*cmd, args->model);
    cmd->add_option("--stepper", args->stepper, "euler, semi-implicit-euler, rk4 (default), dopri5, analytic");
    cmd->add_option("--dt", args->dt, "step in s (default 1/60)");
    cmd->add_option("--tol", args->tol, "tolerance of dopri5 and of the guard's rosenbrock4 (default 1e-9)");
    cmd->add_option("--until-t", args->untilT, "stop at this time instead of at landing");
    cmd->add_option("--max-t", args->maxT, "stop at this time at the latest (default 60 s)");
    cmd->add_flag("--no-guard", args->noGuard,
                  "do not guard stiff drag with sub-steps or rosenbrock4 (shows plain fixed-step behaviour)");
    cmd->add_flag("--json", args->json, "print one JSON object");
    return [args]
    {
        return runPredict(*args);
    };
}

} // namespace abalike::app
