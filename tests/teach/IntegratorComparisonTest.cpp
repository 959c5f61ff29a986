#include <abalike/flight/ClosedForm.hpp>
#include <abalike/teach/IntegratorComparison.hpp>
#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>

namespace abalike
{
namespace
{

constexpr double kPhysicsDt = 1.0 / 60.0;

/// The accuracy bench's problem: the red bird at 30 m/s and 50 degrees into a (-6, 1.5) m/s wind, to the ground.
struct Problem
{
    FlightModel model;
    FlightState s0 = launchState(0.0, 1.5, 30.0, 50.0);
    PredictionLimits limits;
    PredictedFlight real;

    Problem()
    {
        model.massKg = 4.0;
        model.quadraticDrag = quadraticDragCoefficient(1.2, 0.47, 0.25);
        model.windX = -6.0;
        model.windY = 1.5;
        limits.stopOnLanding = true;
        limits.landingY = 0.0;
        IntegratorSettings settings;
        settings.dtS = kPhysicsDt;
        real = predictFlight(model, settings, s0, limits);
    }

    IntegratorComparison compare(StepperKind stepper, double dt, double tol = 1e-6) const
    {
        return compareIntegrator(model, s0, ComparisonMethod{stepper, dt, tol}, kPhysicsDt, real, limits);
    }
};

TEST(IntegratorComparison, RealRk4AgainstItselfIsExact)
{
    const Problem p;
    const IntegratorComparison same = p.compare(StepperKind::Rk4, kPhysicsDt);
    EXPECT_EQ(same.maxErrorM, 0.0);
    EXPECT_EQ(same.flight.path.size(), p.real.path.size());
}

TEST(IntegratorComparison, WhatEachMethodCostsComesWithTheResultWhenAskedFor)
{
    // The teaching overlay asks the core once for the paths and their costs; a caller that does not ask waits for no
    // timing.
    const Problem p;
    const IntegratorComparison plain = p.compare(StepperKind::Euler, 1.0 / 120.0);
    EXPECT_FALSE(plain.costUs.has_value());
    EXPECT_FALSE(plain.realCostUs.has_value());
    const IntegratorComparison timed =
        compareIntegrator(p.model, p.s0, ComparisonMethod{StepperKind::Euler, 1.0 / 120.0}, kPhysicsDt, p.real,
                          p.limits, ComparisonCost::Measure);
    ASSERT_TRUE(timed.costUs && timed.realCostUs);
    EXPECT_GT(*timed.costUs, 0.0);
    EXPECT_GT(*timed.realCostUs, 0.0);
    EXPECT_EQ(timed.flight.path.size(), plain.flight.path.size()); // timing does not change what is compared
    EXPECT_EQ(timed.maxErrorM, plain.maxErrorM);
}

TEST(IntegratorComparison, ErrorsRankTheMethodsAndFollowTheirOrder)
{
    const Problem p;
    const double euler = p.compare(StepperKind::Euler, kPhysicsDt).maxErrorM;
    const double semi = p.compare(StepperKind::SemiImplicitEuler, kPhysicsDt).maxErrorM;
    const double coarseRk4 = p.compare(StepperKind::Rk4, 1.0 / 15.0).maxErrorM;
    const double dopri = p.compare(StepperKind::Dopri5, kPhysicsDt, 1e-10).maxErrorM;
    // At 1/60 s both Euler methods are decimetres off (README: 0.13 m and 0.6 m over 4 s); RK4 at 1/15 s is still
    // within a millimetre; dopri5 at 1e-10 agrees with RK4 at 1/60 s to RK4's own error (nanometres).
    EXPECT_GT(euler, 0.05);
    EXPECT_LT(euler, 1.0);
    EXPECT_GT(semi, 0.05);
    EXPECT_LT(coarseRk4, 1e-3);
    EXPECT_GT(coarseRk4, 1e-7);
    EXPECT_LT(dopri, 1e-7);
    // First order: half the step, about half the error.
    const double eulerHalf = p.compare(StepperKind::Euler, kPhysicsDt / 2.0).maxErrorM;
    EXPECT_NEAR(euler / eulerHalf, 2.0, 0.2);
    // Fourth order: half the step, about a sixteenth.
    const double rk4Half = p.compare(StepperKind::Rk4, 1.0 / 30.0).maxErrorM;
    EXPECT_NEAR(coarseRk4 / rk4Half, 16.0, 3.0);
}

TEST(IntegratorComparison, ErrorIsMeasuredOnTheRealPathBetweenItsPoints)
{
    // In vacuum the real path is the exact parabola; a coarse Euler path is compared with it at Euler's own times,
    // which fall between the real path's points.
    FlightModel vacuum;
    PredictionLimits limits;
    limits.untilTimeS = 2.0;
    const FlightState s0 = launchState(0.0, 0.0, 20.0, 45.0);
    IntegratorSettings settings;
    const PredictedFlight real = predictFlight(vacuum, settings, s0, limits);
    const IntegratorComparison euler =
        compareIntegrator(vacuum, s0, ComparisonMethod{StepperKind::Euler, 1.0 / 22.0, 0.0}, kPhysicsDt, real, limits);
    double worst = 0.0;
    for (const PathPoint& point : euler.flight.path)
    {
        const FlightState exact = *closedFormState(vacuum, s0, point.timeS);
        worst = std::max(
            worst, std::hypot(point.state.position.x - exact.position.x, point.state.position.y - exact.position.y));
    }
    EXPECT_NEAR(euler.maxErrorM, worst, 1e-12);
    // Explicit Euler in vacuum is off by g t h / 2 in height.
    EXPECT_NEAR(worst, 9.81 * 2.0 * (1.0 / 22.0) / 2.0, 0.05 * worst);
}

TEST(IntegratorComparison, ContactErrorWhenBothTouch)
{
    const Problem base;
    Problem p;
    // A wall at x = 30 m.
    p.limits.contact = [](const FlightState& a, const FlightState& b) -> std::optional<double>
    {
        if (a.position.x < 30.0 && b.position.x >= 30.0)
            return (30.0 - a.position.x) / (b.position.x - a.position.x);
        return std::nullopt;
    };
    IntegratorSettings settings;
    p.real = predictFlight(p.model, settings, p.s0, p.limits);
    ASSERT_TRUE(p.real.contact);
    const IntegratorComparison euler = p.compare(StepperKind::Euler, kPhysicsDt);
    ASSERT_TRUE(euler.contactErrorM);
    EXPECT_GT(*euler.contactErrorM, 0.01);
    EXPECT_FALSE(base.compare(StepperKind::Euler, kPhysicsDt).contactErrorM); // landings are no contacts
}

TEST(IntegratorComparison, LabelsAndLimits)
{
    EXPECT_EQ((ComparisonMethod{StepperKind::Euler, 1.0 / 60.0, 0.0}.label()), "explicit Euler, dt = 1/60 s");
    EXPECT_EQ((ComparisonMethod{StepperKind::SemiImplicitEuler, 1.0 / 15.0, 0.0}.label()),
              "semi-implicit Euler, dt = 1/15 s");
    EXPECT_EQ((ComparisonMethod{StepperKind::Dopri5, 0.0, 1e-6}.label()), "dopri5, tol = 1e-06");
    const Problem p;
    EXPECT_THROW(p.compare(StepperKind::Rk4, 1.0 / 10.0), std::invalid_argument);
    EXPECT_THROW(p.compare(StepperKind::Euler, 1.0 / 500.0), std::invalid_argument);
    EXPECT_THROW(p.compare(StepperKind::Dopri5, kPhysicsDt, 1e-13), std::invalid_argument);
    EXPECT_THROW(p.compare(StepperKind::Analytic, kPhysicsDt), std::invalid_argument);
    EXPECT_NO_THROW(p.compare(StepperKind::Rk4, 1.0 / 240.0));
}

} // namespace
} // namespace abalike
