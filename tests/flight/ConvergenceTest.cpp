#include <abalike/flight/ClosedForm.hpp>
#include <abalike/flight/FlightIntegrator.hpp>
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace abalike
{
namespace
{

/// Linear drag with wind: a closed form exists, and every term but quadratic drag is exercised.
FlightModel linearDragWithWind()
{
    FlightModel model;
    model.massKg = 1.0;
    model.linearDrag = 0.5;
    model.windX = 2.0;
    model.windY = -1.0;
    return model;
}

/// Position error after flying 2 s in steps of 2 s / n, against the closed form.
double positionError(StepperKind stepper, int n)
{
    const FlightModel model = linearDragWithWind();
    IntegratorSettings settings;
    settings.stepper = stepper;
    settings.dtS = 2.0 / n;
    FlightIntegrator integrator(model, settings);
    const FlightState s0 = launchState(0.0, 0.0, 20.0, 45.0);
    integrator.reset(0.0, s0);
    for (int i = 0; i < n; ++i)
        integrator.step();
    const FlightState exact = *closedFormState(model, s0, integrator.time());
    return std::hypot(integrator.state().position.x - exact.position.x,
                      integrator.state().position.y - exact.position.y);
}

/// Least-squares slope of log(error) against log(dt) over dt = 2 s / n for the given n.
double measuredOrder(StepperKind stepper, const std::vector<int>& steps)
{
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (const int n : steps)
    {
        const double x = std::log(2.0 / n);
        const double y = std::log(positionError(stepper, n));
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    const double count = static_cast<double>(steps.size());
    return (count * sxy - sx * sy) / (count * sxx - sx * sx);
}

TEST(Convergence, Rk4IsFourthOrderOnLinearDrag)
{
    // dt from 0.1 s to 6 ms: errors from ~1e-5 m down to ~1e-10 m, well above rounding.
    const double order = measuredOrder(StepperKind::Rk4, {20, 40, 80, 160, 320});
    EXPECT_GE(order, 3.8);
    EXPECT_LE(order, 4.2);
}

TEST(Convergence, EulerIsFirstOrder)
{
    const double order = measuredOrder(StepperKind::Euler, {80, 160, 320, 640, 1280});
    EXPECT_GE(order, 0.9);
    EXPECT_LE(order, 1.1);
}

TEST(Convergence, SemiImplicitEulerIsFirstOrder)
{
    const double order = measuredOrder(StepperKind::SemiImplicitEuler, {80, 160, 320, 640, 1280});
    EXPECT_GE(order, 0.9);
    EXPECT_LE(order, 1.1);
}

TEST(Convergence, Rk4AtSixtyHertzIsWithinAMicrometre)
{
    // The preview's own setting: 120 steps of 1/60 s on a 2 s flight.
    EXPECT_LT(positionError(StepperKind::Rk4, 120), 1e-6);
}

} // namespace
} // namespace abalike
