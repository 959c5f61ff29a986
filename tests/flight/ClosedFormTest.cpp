#include <abalike/flight/ClosedForm.hpp>
#include <abalike/flight/FlightIntegrator.hpp>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

/// Each of the four numbers of s within tolerance(its exact value) of exact.
void expectNear(const FlightState& s, const FlightState& exact, double (*tolerance)(double))
{
    EXPECT_NEAR(s.position.x, exact.position.x, tolerance(exact.position.x));
    EXPECT_NEAR(s.position.y, exact.position.y, tolerance(exact.position.y));
    EXPECT_NEAR(s.velocity.x, exact.velocity.x, tolerance(exact.velocity.x));
    EXPECT_NEAR(s.velocity.y, exact.velocity.y, tolerance(exact.velocity.y));
}

FlightState fly(const FlightModel& model, const IntegratorSettings& settings, const FlightState& s0, int steps)
{
    FlightIntegrator integrator(model, settings);
    integrator.reset(0.0, s0);
    for (int i = 0; i < steps; ++i)
        integrator.step();
    return integrator.state();
}

TEST(ClosedForm, VacuumIsTheParabola)
{
    const FlightModel vacuum;
    const FlightState s0 = launchState(1.0, 2.0, 25.0, 30.0);
    const double t = 1.7;
    const FlightState s = *closedFormState(vacuum, s0, t);
    EXPECT_DOUBLE_EQ(s.position.x, 1.0 + s0.velocity.x * t);
    EXPECT_DOUBLE_EQ(s.position.y, 2.0 + s0.velocity.y * t - 0.5 * 9.81 * t * t);
    EXPECT_DOUBLE_EQ(s.velocity.x, s0.velocity.x);
    EXPECT_DOUBLE_EQ(s.velocity.y, s0.velocity.y - 9.81 * t);
}

TEST(ClosedForm, LinearDragSatisfiesItsOde)
{
    // d/dt of the closed form, by a central difference, must be the right-hand side.
    FlightModel model;
    model.linearDrag = 0.8;
    model.massKg = 2.0;
    model.windX = 3.0;
    const FlightState s0 = launchState(0.0, 0.0, 30.0, 60.0);
    const double k = model.linearDrag / model.massKg;
    for (const double t : {0.1, 1.0, 5.0})
    {
        const double h = 1e-5;
        const FlightState a = *closedFormState(model, s0, t - h);
        const FlightState b = *closedFormState(model, s0, t + h);
        const FlightState s = *closedFormState(model, s0, t);
        EXPECT_NEAR((b.position.x - a.position.x) / (2 * h), s.velocity.x, 1e-6);
        EXPECT_NEAR((b.position.y - a.position.y) / (2 * h), s.velocity.y, 1e-6);
        EXPECT_NEAR((b.velocity.x - a.velocity.x) / (2 * h), -k * (s.velocity.x - 3.0), 1e-6);
        EXPECT_NEAR((b.velocity.y - a.velocity.y) / (2 * h), -9.81 - k * s.velocity.y, 1e-6);
    }
    // Long after launch the bird falls at the terminal velocity g m / b, drifting with the wind.
    const FlightState late = *closedFormState(model, s0, 200.0);
    EXPECT_NEAR(late.velocity.x, 3.0, 1e-9);
    EXPECT_NEAR(late.velocity.y, -9.81 / k, 1e-9);
}

TEST(ClosedForm, NoneForQuadraticDragOrGusts)
{
    FlightModel quadratic;
    quadratic.quadraticDrag = 0.02;
    EXPECT_FALSE(hasClosedForm(quadratic));
    EXPECT_FALSE(closedFormState(quadratic, {}, 1.0).has_value());
    FlightModel gusty;
    gusty.linearDrag = 0.1;
    gusty.gusts = GustDef{};
    EXPECT_FALSE(hasClosedForm(gusty));
    FlightModel windOnly; // wind without drag does nothing: still the parabola
    windOnly.windX = 5.0;
    EXPECT_TRUE(hasClosedForm(windOnly));
}

TEST(ClosedForm, Rk4MatchesVacuumToRounding)
{
    // RK4 is exact on polynomials of degree <= 4 in t; the vacuum flight is quadratic.
    const FlightModel vacuum;
    const FlightState s0 = launchState(0.0, 0.0, 20.0, 45.0);
    const FlightState s = fly(vacuum, {}, s0, 180);
    const FlightState exact = *closedFormState(vacuum, s0, 3.0);
    expectNear(s, exact, [](double) { return 1e-11; });
}

TEST(ClosedForm, AnalyticStepperIsExact)
{
    FlightModel model;
    model.linearDrag = 0.3;
    model.windX = -4.0;
    model.windY = 1.0;
    IntegratorSettings settings;
    settings.stepper = StepperKind::Analytic;
    settings.dtS = 0.25; // large steps: the closed form does not care
    const FlightState s0 = launchState(5.0, 1.0, 40.0, 70.0);
    const FlightState s = fly(model, settings, s0, 40);
    const FlightState exact = *closedFormState(model, s0, 10.0);
    expectNear(s, exact, [](double x) { return 1e-12 * (1.0 + std::abs(x)); });
}

TEST(ClosedForm, AnalyticStepperRefusesQuadraticDrag)
{
    FlightModel model;
    model.quadraticDrag = 0.02;
    IntegratorSettings settings;
    settings.stepper = StepperKind::Analytic;
    EXPECT_THROW(FlightIntegrator(model, settings), std::invalid_argument);
}

TEST(ClosedForm, Dopri5IsWithinItsTolerance)
{
    FlightModel model;
    model.linearDrag = 0.5;
    model.windX = 2.0;
    const FlightState s0 = launchState(0.0, 0.0, 30.0, 45.0);
    const FlightState exact = *closedFormState(model, s0, 4.0);
    for (const double tol : {1e-6, 1e-9, 1e-12})
    {
        IntegratorSettings settings;
        settings.stepper = StepperKind::Dopri5;
        settings.tolerance = tol;
        const FlightState s = fly(model, settings, s0, 240);
        const double error = std::hypot(s.position.x - exact.position.x, s.position.y - exact.position.y);
        // Tolerance is per step and relative to the state's size (~50 m here); a flight accumulates a few.
        EXPECT_LT(error, 100.0 * tol * 50.0) << "tol " << tol;
    }
}

} // namespace
} // namespace abalike
