#include <abalike/flight/ClosedForm.hpp>
#include <abalike/teach/FlightEnergy.hpp>
#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>

namespace abalike
{
namespace
{

FlightModel redBirdInWind(double windX, double windY)
{
    FlightModel model;
    model.massKg = 4.0;
    model.quadraticDrag = 0.055;
    model.windX = windX;
    model.windY = windY;
    return model;
}

double launchEnergy(const FlightEnergy& e)
{
    return e.launchKineticJ + e.launchPotentialJ;
}

TEST(FlightEnergy, VacuumHasNoDragLossAndConservesEnergy)
{
    const FlightState s0 = launchState(0.0, 1.5, 20.0, 55.0);
    const FlightEnergy e = flightEnergyAt(FlightModel{}, {}, s0, 2.0);
    EXPECT_EQ(e.dragLossJ, 0.0);
    EXPECT_NEAR(e.balanceResidualJ(), 0.0, 1e-12 * launchEnergy(e));
    EXPECT_DOUBLE_EQ(e.launchKineticJ, 0.5 * 20.0 * 20.0);
    EXPECT_DOUBLE_EQ(e.launchPotentialJ, 9.81 * 1.5);
    const FlightState exact = *closedFormState(FlightModel{}, s0, 2.0);
    EXPECT_NEAR(e.state.position.y, exact.position.y, 1e-12);
    EXPECT_NEAR(e.potentialJ, 9.81 * exact.position.y, 1e-10);
}

TEST(FlightEnergy, DragAndWindBalanceClosesToTheIntegratorsAccuracy)
{
    const FlightModel model = redBirdInWind(-6.0, 1.5);
    const FlightState s0 = launchState(0.0, 1.5, 30.0, 50.0);
    for (const double t : {0.01, 0.5, 1.2345, 3.0})
    {
        const FlightEnergy e = flightEnergyAt(model, {}, s0, t);
        EXPECT_GT(e.dragLossJ, 0.0);
        EXPECT_NEAR(e.balanceResidualJ(), 0.0, 1e-9 * launchEnergy(e)) << t;
    }
    // Fourth order: with half the step the residual falls by about 16.
    IntegratorSettings coarse;
    coarse.dtS = 1.0 / 15.0;
    IntegratorSettings half;
    half.dtS = 1.0 / 30.0;
    const double r1 = std::abs(flightEnergyAt(model, coarse, s0, 3.0).balanceResidualJ());
    const double r2 = std::abs(flightEnergyAt(model, half, s0, 3.0).balanceResidualJ());
    EXPECT_GT(r1 / r2, 10.0);
    EXPECT_LT(r1 / r2, 40.0);
}

TEST(FlightEnergy, LinearDragLossMatchesTheClosedForm)
{
    FlightModel model;
    model.linearDrag = 0.3;
    model.windX = 2.0;
    const FlightState s0 = launchState(0.0, 0.0, 25.0, 40.0);
    const double t = 2.5;
    const FlightState exact = *closedFormState(model, s0, t);
    const double exactLoss = 0.5 * (s0.velocity.x * s0.velocity.x + s0.velocity.y * s0.velocity.y) -
                             0.5 * (exact.velocity.x * exact.velocity.x + exact.velocity.y * exact.velocity.y) -
                             9.81 * exact.position.y;
    const FlightEnergy e = flightEnergyAt(model, {}, s0, t);
    EXPECT_NEAR(e.dragLossJ, exactLoss, 1e-7);
}

TEST(FlightEnergy, ATailwindAddsEnergy)
{
    // The air moves faster than the bird: drag pushes it forward and the "loss" is negative.
    const FlightModel model = redBirdInWind(40.0, 0.0);
    const FlightEnergy e = flightEnergyAt(model, {}, launchState(0.0, 1.0, 10.0, 30.0), 1.0);
    EXPECT_LT(e.dragLossJ, 0.0);
    EXPECT_NEAR(e.balanceResidualJ(), 0.0, 1e-9 * launchEnergy(e));
}

TEST(FlightEnergy, StepwiseGustsInsideAStepKeepTheBalance)
{
    FlightModel model = redBirdInWind(0.0, 0.0);
    model.gusts = GustDef{};
    model.gusts->steps = {{0.51, -10.0, 0.0}, {1.337, 3.0, 2.0}}; // inside steps, not on their boundaries
    const FlightState s0 = launchState(0.0, 1.5, 28.0, 45.0);
    const FlightEnergy e = flightEnergyAt(model, {}, s0, 2.2);
    EXPECT_NEAR(e.balanceResidualJ(), 0.0, 1e-9 * launchEnergy(e));
    // Inside the step of a jump too.
    const FlightEnergy atJump = flightEnergyAt(model, {}, s0, 0.515);
    EXPECT_NEAR(atJump.balanceResidualJ(), 0.0, 1e-9 * launchEnergy(atJump));
}

TEST(FlightEnergy, TrackerGoesForwardAndStartsOverForAnEarlierTime)
{
    const FlightModel model = redBirdInWind(-3.0, 0.0);
    const FlightState s0 = launchState(0.0, 1.5, 25.0, 40.0);
    FlightEnergyTracker tracker(model, {}, s0);
    const FlightEnergy late = tracker.at(2.0);
    const FlightEnergy early = tracker.at(0.7);
    EXPECT_EQ(early.dragLossJ, flightEnergyAt(model, {}, s0, 0.7).dragLossJ);
    EXPECT_EQ(tracker.at(2.0).dragLossJ, late.dragLossJ);
    EXPECT_EQ(tracker.at(0.0).dragLossJ, 0.0);
    EXPECT_THROW(tracker.at(-1.0), std::invalid_argument);
    EXPECT_THROW(tracker.at(NAN), std::invalid_argument);
}

} // namespace
} // namespace abalike
