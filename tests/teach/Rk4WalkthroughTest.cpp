#include <abalike/flight/ClosedForm.hpp>
#include <abalike/flight/FlightIntegrator.hpp>
#include <abalike/teach/Rk4Walkthrough.hpp>
#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>

namespace abalike
{
namespace
{

/// s + k slope.
FlightState plus(const FlightState& s, double k, const FlightState& slope)
{
    return {s.position + k * slope.position, s.velocity + k * slope.velocity};
}

/// Each of the four numbers within tolerance (scaled by scale(expected number) when given).
void expectState(const FlightState& actual, const FlightState& expected, double tolerance,
                 double (*scale)(double) = nullptr)
{
    const auto near = [&](double a, double e, const char* name)
    {
        EXPECT_NEAR(a, e, scale != nullptr ? scale(e) * tolerance : tolerance) << name;
    };
    near(actual.position.x, expected.position.x, "position.x");
    near(actual.position.y, expected.position.y, "position.y");
    near(actual.velocity.x, expected.velocity.x, "velocity.x");
    near(actual.velocity.y, expected.velocity.y, "velocity.y");
}

/// Spec section 16.1: x0 = y0 = 0, vx0 = vy0 = 10 m/s, dt = 1 s, g = 9.81 along -y, worked by hand.
TEST(Rk4Walkthrough, ReproducesTheSpecsWorkedExample)
{
    const Rk4Walkthrough walk = walkRk4Step(FlightModel{}, 0.0, {{0.0, 0.0}, {10.0, 10.0}}, 1.0);
    // k1 = f(state); k2 = f(state + k1/2): y = 5, vy = 10 - 4.905; k3 = f(state + k2/2): y = 2.5475, vy = 5.095;
    // k4 = f(state + k3): y = 5.095, vy = 0.19.
    expectState(walk.stages[0].slope, {{10.0, 10.0}, {0.0, -9.81}}, 1e-12);
    expectState(walk.stages[1].slope, {{10.0, 5.095}, {0.0, -9.81}}, 1e-12);
    expectState(walk.stages[2].slope, {{10.0, 5.095}, {0.0, -9.81}}, 1e-12);
    expectState(walk.stages[3].slope, {{10.0, 0.19}, {0.0, -9.81}}, 1e-12);
    expectState(walk.stages[1].at, {{5.0, 5.0}, {10.0, 5.095}}, 1e-12);
    expectState(walk.stages[2].at, {{5.0, 2.5475}, {10.0, 5.095}}, 1e-12);
    expectState(walk.stages[3].at, {{10.0, 5.095}, {10.0, 0.19}}, 1e-12);
    EXPECT_DOUBLE_EQ(walk.stages[1].tS, 0.5);
    EXPECT_DOUBLE_EQ(walk.stages[3].tS, 1.0);
    // y1 = (10 + 2 * 5.095 + 2 * 5.095 + 0.19) / 6 = 5.095: RK4 is exact for the parabola.
    expectState(walk.averageSlope, {{10.0, 5.095}, {0.0, -9.81}}, 1e-12);
    expectState(walk.next, {{10.0, 5.095}, {10.0, 0.19}}, 1e-12);
    ASSERT_TRUE(walk.exact);
    expectState(*walk.exact, {{10.0, 5.095}, {10.0, 0.19}}, 1e-12);
}

/// The walkthrough's step is the integrator's step, bit for bit: what the panel shows is what the preview does.
TEST(Rk4Walkthrough, NextIsTheIntegratorsStepExactly)
{
    FlightModel model;
    model.massKg = 4.0;
    model.quadraticDrag = 0.055;
    model.linearDrag = 0.02;
    model.windX = -6.0;
    model.windY = 1.5;
    const FlightState s0 = launchState(1.0, 2.5, 27.0, 37.0);
    IntegratorSettings settings;
    FlightIntegrator integrator(model, settings);
    integrator.reset(0.0, s0);
    const FlightState stepped = integrator.step().s1;
    const Rk4Walkthrough walk = walkRk4Step(model, 0.0, s0, settings.dtS);
    expectState(walk.next, stepped, 0.0);
    // Later in a flight the integrator steps by (t + dt) - t, which rounds differently from dt in the last bit.
    integrator.reset(0.25, s0);
    const FlightState later = integrator.step().s1;
    const Rk4Walkthrough laterWalk = walkRk4Step(model, 0.25, s0, settings.dtS);
    expectState(laterWalk.next, later, 1e-14, [](double x) { return std::abs(x) + 0.1; });
    EXPECT_FALSE(walk.exact); // quadratic drag has no closed form
}

TEST(Rk4Walkthrough, SlopesAreDerivativesWhereTheyAreEvaluated)
{
    FlightModel model;
    model.quadraticDrag = 0.1;
    model.massKg = 2.0;
    model.gusts = GustDef{};
    model.gusts->kind = GustDef::Kind::Sine;
    model.gusts->amplitudeX = 4.0;
    model.gusts->periodS = 2.0;
    const FlightState s = {{0.0, 1.0}, {20.0, 5.0}};
    const double h = 0.1;
    const Rk4Walkthrough walk = walkRk4Step(model, 0.3, s, h);
    const FlightIntegrator rhs(model, {});
    const double stageOffsets[] = {0.0, 0.5, 0.5, 1.0};
    for (std::size_t k = 0; k < 4; ++k)
    {
        EXPECT_DOUBLE_EQ(walk.stages[k].tS, 0.3 + stageOffsets[k] * h);
        expectState(walk.stages[k].slope, rhs.rightHandSide(walk.stages[k].tS, walk.stages[k].at), 0.0);
        // Stage k + 1 is evaluated at state + c h k_k: increments are slopes times the stage's share of the step.
        if (k < 3)
        {
            expectState(walk.stages[k + 1].at, plus(s, stageOffsets[k + 1] * h, walk.stages[k].slope), 1e-12);
        }
    }
    expectState(walk.next, plus(s, h, walk.averageSlope), 1e-12);
}

TEST(Rk4Walkthrough, ExactWithLinearDragAndWindShowsTheFifthOrderLocalError)
{
    FlightModel model;
    model.linearDrag = 0.5;
    model.windX = 3.0;
    const FlightState s = {{0.0, 0.0}, {10.0, 10.0}};
    // Local error of RK4 is O(h^5): halving the step divides it by about 32.
    const auto error = [&](double h)
    {
        const Rk4Walkthrough walk = walkRk4Step(model, 0.0, s, h);
        EXPECT_TRUE(walk.exact);
        return std::hypot(walk.next.velocity.x - (*walk.exact).velocity.x,
                          walk.next.velocity.y - (*walk.exact).velocity.y);
    };
    const double ratio = error(0.2) / error(0.1);
    EXPECT_GT(ratio, 28.0);
    EXPECT_LT(ratio, 36.0);
    EXPECT_GT(error(0.1), 0.0);
}

TEST(Rk4Walkthrough, RejectsInvalidInput)
{
    EXPECT_THROW(walkRk4Step(FlightModel{}, 0.0, {{0, 0}, {1, 1}}, 0.0), std::invalid_argument);
    EXPECT_THROW(walkRk4Step(FlightModel{}, 0.0, {{0, 0}, {1, 1}}, -1.0), std::invalid_argument);
    EXPECT_THROW(walkRk4Step(FlightModel{}, 0.0, {{0, 0}, {NAN, 1}}, 1.0), std::invalid_argument);
    EXPECT_THROW(walkRk4Step(FlightModel{}, INFINITY, {{0, 0}, {1, 1}}, 1.0), std::invalid_argument);
    FlightModel massless;
    massless.massKg = 0.0;
    EXPECT_THROW(walkRk4Step(massless, 0.0, {{0, 0}, {1, 1}}, 1.0), std::invalid_argument);
}

} // namespace
} // namespace abalike
