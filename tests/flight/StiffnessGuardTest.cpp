#include <abalike/flight/ClosedForm.hpp>
#include <abalike/flight/FlightIntegrator.hpp>
#include <abalike/flight/Prediction.hpp>
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace abalike
{
namespace
{

struct StiffCase
{
    const char* name;
    double massKg;
    double linearDrag;
    double quadraticDrag;
    double speedMps;
};

std::ostream& operator<<(std::ostream& out, const StiffCase& c)
{
    return out << c.name;
}

FlightModel modelOf(const StiffCase& c)
{
    FlightModel model;
    model.massKg = c.massKg;
    model.linearDrag = c.linearDrag;
    model.quadraticDrag = c.quadraticDrag;
    return model;
}

/// Positions at each 1/60 s output step for 3 s.
std::vector<FlightState> flyPath(const FlightModel& model, const IntegratorSettings& settings, const FlightState& s0)
{
    FlightIntegrator integrator(model, settings);
    integrator.reset(0.0, s0);
    std::vector<FlightState> path;
    for (int i = 0; i < 180; ++i)
        path.push_back(integrator.step().s1);
    return path;
}

/// Largest position error along the path relative to the largest distance flown.
double relativeError(const std::vector<FlightState>& path, const std::vector<FlightState>& reference,
                     const FlightState& s0)
{
    double worst = 0.0;
    double scale = 0.0;
    for (std::size_t i = 0; i < path.size(); ++i)
    {
        const double e =
            std::hypot(path[i].position.x - reference[i].position.x, path[i].position.y - reference[i].position.y);
        worst = std::isfinite(e) ? std::max(worst, e) : INFINITY;
        scale = std::max(scale,
                         std::hypot(reference[i].position.x - s0.position.x, reference[i].position.y - s0.position.y));
    }
    return worst / scale;
}

class StiffDrag : public testing::TestWithParam<StiffCase>
{
};

TEST_P(StiffDrag, GuardedRk4StaysWithin1e3OfTheReferenceWherePlainRk4Diverges)
{
    const StiffCase& c = GetParam();
    const FlightModel model = modelOf(c);
    const FlightState s0 = launchState(0.0, 0.0, c.speedMps, 45.0);

    IntegratorSettings reference;
    reference.stepper = StepperKind::Dopri5;
    reference.tolerance = 1e-12;
    const auto exact = flyPath(model, reference, s0);

    IntegratorSettings plain;
    plain.guardStiffness = false;
    // Sanity of the premise: |lambda| dt at launch is far beyond RK4's stability limit of 2.785.
    FlightIntegrator probe(model, plain);
    probe.reset(0.0, s0);
    probe.step();
    EXPECT_GT(probe.maxStiffnessRatio(), 2.785);
    EXPECT_FALSE(relativeError(flyPath(model, plain, s0), exact, s0) < 1.0) << "plain RK4 should diverge";

    const IntegratorSettings guarded; // the preview's defaults: RK4, 1/60 s, guard on
    EXPECT_LT(relativeError(flyPath(model, guarded, s0), exact, s0), 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Cases, StiffDrag,
                         testing::Values(StiffCase{"LightBird", 0.01, 0.0, 0.05, 50.0},
                                         StiffCase{"VeryLightFastBird", 0.001, 0.0, 0.05, 200.0},
                                         StiffCase{"FeatherAt1000", 1e-4, 0.0, 0.05, 1000.0},
                                         StiffCase{"StrongLinearDrag", 1e-4, 1.0, 0.0, 50.0}),
                         [](const testing::TestParamInfo<StiffCase>& info) { return std::string(info.param.name); });

TEST(StiffnessGuard, PersistentStiffnessIsHandedToRosenbrock4AndStaysExact)
{
    // Linear drag on a 0.1 g bird: |lambda| dt = 167 on every step, not just at launch. Explicit sub-steps would
    // need 334 per step forever; the guard hands such steps to the implicit stepper.
    FlightModel model;
    model.massKg = 1e-4;
    model.linearDrag = 1.0;
    const FlightState s0 = launchState(0.0, 0.0, 50.0, 45.0);
    FlightIntegrator integrator(model, {});
    integrator.reset(0.0, s0);
    for (int i = 0; i < 600; ++i)
        integrator.step();
    EXPECT_EQ(integrator.guardAction(), GuardAction::Implicit);
    EXPECT_LT(integrator.substeps(), 2000u);
    const FlightState exact = *closedFormState(model, s0, integrator.time());
    EXPECT_NEAR(integrator.state().position.x, exact.position.x, 1e-6);
    EXPECT_NEAR(integrator.state().position.y, exact.position.y, 1e-6);
}

TEST(StiffnessGuard, ModerateStiffnessIsSubSteppedNotImplicit)
{
    FlightModel model;
    model.massKg = 0.1;
    model.quadraticDrag = 0.05;
    const PredictedFlight flight = predictFlight(model, {}, launchState(0, 0, 200, 45), {});
    EXPECT_EQ(flight.guard, GuardAction::Substep);
    EXPECT_GT(flight.substeps, 0u);
    EXPECT_LE(flight.maxStiffnessRatio, defaultGuardLimit(StepperKind::Rk4) + 1e-12);
}

TEST(StiffnessGuard, NothingToDoWithoutDrag)
{
    const PredictedFlight flight = predictFlight(FlightModel{}, {}, launchState(0, 0, 1000, 45), {});
    EXPECT_EQ(flight.guard, GuardAction::None);
    EXPECT_EQ(flight.substeps, 0u);
    IntegratorSettings off;
    off.guardStiffness = false;
    EXPECT_EQ(predictFlight(FlightModel{}, off, launchState(0, 0, 10, 45), {}).guard, GuardAction::Off);
}

TEST(StiffnessGuard, GuardedEulerIsStable)
{
    FlightModel model;
    model.massKg = 0.01;
    model.quadraticDrag = 0.05;
    for (const StepperKind stepper : {StepperKind::Euler, StepperKind::SemiImplicitEuler})
    {
        IntegratorSettings settings;
        settings.stepper = stepper;
        const PredictedFlight flight = predictFlight(model, settings, launchState(0, 0, 50, 45), {});
        const FlightState& end = flight.path.back().state;
        EXPECT_TRUE(std::isfinite(end.position.x) && std::isfinite(end.position.y)) << stepperName(stepper);
        // Falling at the terminal velocity sqrt(m g / c) = 1.4 m/s.
        EXPECT_NEAR(end.velocity.y, -std::sqrt(0.01 * 9.81 / 0.05), 1e-3) << stepperName(stepper);
    }
}

} // namespace
} // namespace abalike
