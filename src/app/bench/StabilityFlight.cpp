#include "bench/StabilityFlight.hpp"
#include <abalike/util/MedianTimer.hpp>

#include <abalike/flight/FlightIntegrator.hpp>
#include <abalike/flight/FlightRhs.hpp>

#include <algorithm>
#include <benchmark/benchmark.h>
#include <cmath>
#include <limits>
#include <sstream>

namespace abalike::app
{

namespace
{

constexpr double kDt = 1.0 / 60.0;

/// The red bird (4 kg, r = 0.25 m, Cd 0.47) in sea-level air.
FlightModel redInAir()
{
    FlightModel model;
    model.massKg = 4.0;
    model.quadraticDrag = quadraticDragCoefficient(1.2, 0.47, 0.25);
    return model;
}

std::string number(double value)
{
    std::ostringstream out;
    out << value;
    return out.str();
}

std::vector<FlightState> fly(const StabilityCase& c, const IntegratorSettings& settings)
{
    FlightIntegrator integrator(c.model, settings);
    integrator.reset(0.0, c.s0);
    const auto steps = static_cast<std::size_t>(std::lround(c.durationS / kDt));
    std::vector<FlightState> path;
    path.reserve(steps);
    for (std::size_t i = 0; i < steps; ++i)
        path.push_back(integrator.step().s1);
    return path;
}

/// Largest position error along the path relative to the largest distance the reference flies from launch
/// (a bird that does not move is compared absolutely).
double relativeError(const std::vector<FlightState>& path, const std::vector<FlightState>& reference,
                     const FlightState& s0)
{
    double worst = 0.0;
    double scale = 0.0;
    for (std::size_t i = 0; i < path.size(); ++i)
    {
        const double e =
            std::hypot(path[i].position.x - reference[i].position.x, path[i].position.y - reference[i].position.y);
        if (!std::isfinite(e))
            return std::numeric_limits<double>::infinity();
        worst = std::max(worst, e);
        scale = std::max(scale,
                         std::hypot(reference[i].position.x - s0.position.x, reference[i].position.y - s0.position.y));
    }
    return scale > 0.0 ? worst / scale : worst;
}

} // namespace

std::vector<StabilityCase> stabilityCases(bool quick)
{
    std::vector<StabilityCase> cases;
    auto add = [&](std::string group, std::string name, const FlightModel& model, const FlightState& s0)
    {
        cases.push_back({std::move(group), std::move(name), model, s0, 60.0});
    };

    // Stiff quadratic drag, 10 g bird, c = 0.05 kg/m: |lambda| dt = 2 c v dt / m at launch, so v = 6 |lambda| dt.
    for (const double ratio : quick ? std::vector<double>{1, 2.78, 10, 100}
                                    : std::vector<double>{0.5, 1, 2, 2.5, 2.7, 2.78, 2.9, 3.5, 5, 10, 100})
    {
        FlightModel model;
        model.massKg = 0.01;
        model.quadraticDrag = 0.05;
        add("stiff quadratic drag", "|lambda| dt " + number(ratio) + " at launch (" + number(6 * ratio) + " m/s)",
            model, launchState(0, 0, 6 * ratio, 45));
    }
    // Stiff linear drag: |lambda| = b / m for the whole flight, so the stability limit is exactly RK4's 2.785.
    for (const double ratio :
         quick ? std::vector<double>{1, 2.78, 50} : std::vector<double>{0.5, 1, 2, 2.7, 2.78, 2.8, 3, 5, 50, 500})
    {
        FlightModel model;
        model.massKg = 0.01;
        model.linearDrag = ratio * model.massKg / kDt;
        add("stiff linear drag", "|lambda| dt " + number(ratio) + " throughout", model, launchState(0, 0, 30, 45));
    }
    for (const double speed : quick ? std::vector<double>{0, 100, 1000} : std::vector<double>{0, 1, 10, 100, 300, 1000})
        add("launch speed", number(speed) + " m/s, red bird in air", redInAir(), launchState(0, 0, speed, 45));
    for (const double speed : quick ? std::vector<double>{1000} : std::vector<double>{100, 1000})
        add("launch speed", number(speed) + " m/s in vacuum", FlightModel{}, launchState(0, 0, speed, 45));
    for (const double angle :
         quick ? std::vector<double>{-90, 0, 90} : std::vector<double>{-90, -60, -30, 0, 30, 60, 90})
        add("launch angle", number(angle) + " deg, 50 m/s, red bird in air", redInAir(), launchState(0, 0, 50, angle));
    for (const double g : quick ? std::vector<double>{0, 0.01, 100} : std::vector<double>{0, 0.01, 1.62, 9.81, 100})
    {
        FlightModel model = redInAir();
        model.gravity = g;
        add("gravity", "g = " + number(g) + " m/s^2, red bird in air", model, launchState(0, 0, 50, 45));
        FlightModel vacuum;
        vacuum.gravity = g;
        if (!quick)
            add("gravity", "g = " + number(g) + " m/s^2, vacuum", vacuum, launchState(0, 0, 50, 45));
    }
    for (const double mass :
         quick ? std::vector<double>{1e-4, 1, 1e4} : std::vector<double>{1e-4, 1e-3, 1e-2, 1, 1e2, 1e4})
    {
        FlightModel model = redInAir();
        model.massKg = mass;
        add("mass", number(mass) + " kg, c = 0.055 kg/m, 50 m/s", model, launchState(0, 0, 50, 45));
    }
    for (const auto& [x0, y0] : quick ? std::vector<std::pair<double, double>>{{1e4, 1e4}}
                                      : std::vector<std::pair<double, double>>{{1e4, 0}, {1e4, 1e4}, {-1e4, -1e4}})
    {
        add("launch point", "(" + number(x0) + ", " + number(y0) + ") m, red bird in air", redInAir(),
            launchState(x0, y0, 50, 45));
        if (!quick)
            add("launch point", "(" + number(x0) + ", " + number(y0) + ") m, vacuum", FlightModel{},
                launchState(x0, y0, 50, 45));
    }
    {
        FlightModel model = redInAir();
        model.massKg = 1e-4;
        model.gravity = 100.0;
        add("combined", "0.1 g bird, g = 100, 1000 m/s, 10 km out", model, launchState(1e4, 1e4, 1000, 30));
        FlightModel gusty = redInAir();
        gusty.windX = -5.0;
        gusty.gusts = GustDef{};
        gusty.gusts->steps = {{1.0, 15.0, 0.0}, {2.5, -10.0, 5.0}, {4.0, 0.0, 0.0}};
        add("combined", "red bird, wind and stepwise gusts", gusty, launchState(0, 0, 40, 50));
        FlightModel light = gusty;
        light.massKg = 0.01;
        light.gusts->kind = GustDef::Kind::Sine;
        light.gusts->amplitudeX = 8.0;
        light.gusts->periodS = 0.7;
        add("combined", "10 g bird, wind and a 0.7 s sine gust", light, launchState(0, 0, 200, 20));
    }
    return cases;
}

StabilityResult runStabilityCase(const StabilityCase& c, bool quick)
{
    StabilityResult result;
    result.launchLambdaDt = visitFlightRhs(c.model, [&](auto rhs) { return rhs.stiffness(c.s0, 0.0) * kDt; });

    IntegratorSettings reference;
    reference.stepper = StepperKind::Dopri5;
    reference.tolerance = 1e-12;
    const std::vector<FlightState> exact = fly(c, reference);
    result.referenceSteps = exact.size();

    IntegratorSettings plain;
    plain.guardStiffness = false;
    const std::vector<FlightState> plainPath = fly(c, plain);
    for (std::size_t i = 0; i < plainPath.size(); ++i)
        if (!std::isfinite(plainPath[i].position.x) || !std::isfinite(plainPath[i].position.y))
        {
            result.plainFinite = false;
            result.plainBlowUpS = static_cast<double>(i + 1) * kDt;
            break;
        }
    result.plainError = relativeError(plainPath, exact, c.s0);

    const IntegratorSettings guarded; // the preview's own settings
    const std::vector<FlightState> guardedPath = fly(c, guarded);
    result.guardedError = relativeError(guardedPath, exact, c.s0);
    {
        FlightIntegrator integrator(c.model, guarded);
        integrator.reset(0.0, c.s0);
        for (std::size_t i = 0; i < guardedPath.size(); ++i)
            integrator.step();
        result.guard = guardActionName(integrator.guardAction());
        result.substeps = integrator.substeps();
    }
    result.guardedUs = 1e6 * medianSeconds([&] { benchmark::DoNotOptimize(fly(c, guarded)); }, quick ? 3 : 7);
    result.passed = std::isfinite(result.guardedError) && result.guardedError <= kStabilityTolerance;
    return result;
}

} // namespace abalike::app
