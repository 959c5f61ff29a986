#include <abalike/flight/ClosedForm.hpp>
#include <abalike/teach/RangeChart.hpp>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <stdexcept>

namespace abalike
{
namespace
{

constexpr double kDeg = std::numbers::pi / 180.0;

RangeLaunch vacuumLaunch(double speed, double height)
{
    RangeLaunch launch;
    launch.speedMps = speed;
    launch.heightM = height;
    return launch;
}

/// Range from height h in vacuum: x where v sin(a) t - g t^2 / 2 = -h.
double vacuumRange(double v, double angleDeg, double h, double g = 9.81)
{
    const double vx = v * std::cos(angleDeg * kDeg);
    const double vy = v * std::sin(angleDeg * kDeg);
    return vx * (vy + std::sqrt(vy * vy + 2.0 * g * h)) / g;
}

TEST(RangeChart, VacuumFromTheGroundPeaksAt45Degrees)
{
    const double v = 20.0;
    const RangeChart chart = rangeChart(vacuumLaunch(v, 0.0), -90.0, 90.0, 1.0);
    ASSERT_EQ(chart.anglesDeg.size(), 181u);
    EXPECT_EQ(chart.anglesDeg.front(), -90.0);
    EXPECT_EQ(chart.anglesDeg.back(), 90.0);
    for (std::size_t i = 0; i < chart.anglesDeg.size(); ++i)
    {
        const double a = chart.anglesDeg[i];
        ASSERT_TRUE(chart.rangesM[i]) << a;
        // Into the ground (and flat along it) is 0; otherwise R = v^2 sin(2a) / g.
        const double expected = a <= 0.0 ? 0.0 : v * v * std::sin(2.0 * a * kDeg) / 9.81;
        EXPECT_NEAR(*chart.rangesM[i], expected, 1e-9 * v * v / 9.81) << a;
    }
    ASSERT_TRUE(chart.bestAngleDeg);
    EXPECT_NEAR(*chart.bestAngleDeg, 45.0, 0.05);
    EXPECT_NEAR(*chart.bestRangeM, v * v / 9.81, 1e-9);
}

TEST(RangeChart, FromAboveTheGroundTheBestAngleIsBelow45)
{
    for (const double h : {1.5, 10.0, 50.0})
    {
        const double v = 20.0;
        const double g = 9.81;
        const RangeChart chart = rangeChart(vacuumLaunch(v, h), -90.0, 90.0, 1.0);
        // The optimum from height h: sin(a) = v / sqrt(2 (v^2 + g h)); its range is v / g sqrt(v^2 + 2 g h).
        const double best = std::asin(v / std::sqrt(2.0 * (v * v + g * h))) / kDeg;
        ASSERT_TRUE(chart.bestAngleDeg);
        EXPECT_LT(*chart.bestAngleDeg, 45.0);
        EXPECT_NEAR(*chart.bestAngleDeg, best, 0.05) << "h = " << h;
        EXPECT_NEAR(*chart.bestRangeM, v / g * std::sqrt(v * v + 2.0 * g * h), 1e-6);
        for (std::size_t i = 0; i < chart.anglesDeg.size(); ++i)
            EXPECT_NEAR(*chart.rangesM[i], vacuumRange(v, chart.anglesDeg[i], h), 1e-8) << chart.anglesDeg[i];
    }
}

TEST(RangeChart, QuadraticDragLowersTheBestAngleAsAFineStepReferenceFinds)
{
    RangeLaunch launch = vacuumLaunch(30.0, 0.0);
    launch.model.massKg = 4.0;
    launch.model.quadraticDrag = 0.055; // the red bird in air
    const RangeChart chart = rangeChart(launch, 0.0, 90.0, 1.0);
    ASSERT_TRUE(chart.bestAngleDeg);
    EXPECT_LT(*chart.bestAngleDeg, 44.0);

    // Reference: 16 times finer steps, every 0.01 degree around the optimum.
    RangeLaunch fine = launch;
    fine.settings.dtS = 1.0 / 960.0;
    double bestAngle = 0.0;
    double bestRange = -1.0;
    for (double a = *chart.bestAngleDeg - 1.0; a <= *chart.bestAngleDeg + 1.0; a += 0.01)
        if (const double r = *rangeAtAngle(fine, a); r > bestRange)
        {
            bestRange = r;
            bestAngle = a;
        }
    EXPECT_NEAR(*chart.bestAngleDeg, bestAngle, 0.05);
    EXPECT_NEAR(*chart.bestRangeM, bestRange, 1e-6);
    for (const double a : {10.0, 35.0, 60.0, 85.0})
        EXPECT_NEAR(*rangeAtAngle(launch, a), *rangeAtAngle(fine, a), 1e-6) << a;
}

/// Linear drag with wind has a closed-form path: its landing, found by bisection on the exact y(t), is the range.
TEST(RangeChart, LinearDragWithWindMatchesTheClosedForm)
{
    RangeLaunch launch = vacuumLaunch(25.0, 3.0);
    launch.model.linearDrag = 0.4;
    launch.model.windX = -5.0;
    for (const double a : {-30.0, 0.0, 20.0, 45.0, 70.0, 89.0})
    {
        const FlightState s0 = launchState(0.0, 3.0, 25.0, a);
        double lo = 0.0;
        double hi = 30.0;
        for (int i = 0; i < 200; ++i)
        {
            const double mid = 0.5 * (lo + hi);
            const FlightState s = *closedFormState(launch.model, s0, mid);
            (s.velocity.y > 0.0 || s.position.y > 0.0 ? lo : hi) = mid;
        }
        const double exact = (*closedFormState(launch.model, s0, lo)).position.x;
        EXPECT_NEAR(*rangeAtAngle(launch, a), exact, 1e-7) << a;
    }
}

TEST(RangeChart, HeadwindRangesAreSignedAndTailwindsCarryFurther)
{
    RangeLaunch calm = vacuumLaunch(15.0, 0.0);
    calm.model.quadraticDrag = 0.05;
    RangeLaunch head = calm;
    head.model.windX = -20.0;
    RangeLaunch tail = calm;
    tail.model.windX = 10.0;
    EXPECT_GT(*rangeAtAngle(tail, 45.0), *rangeAtAngle(calm, 45.0));
    EXPECT_LT(*rangeAtAngle(head, 45.0), *rangeAtAngle(calm, 45.0));
    // A steep shot into a gale comes down behind the slingshot: negative range.
    EXPECT_LT(*rangeAtAngle(head, 80.0), 0.0);
}

TEST(RangeChart, ASlowLaunchLandsInsideItsFirstStep)
{
    // At 0.5 m/s and 30 degrees the bird is back on the ground after 0.051 s, inside the first 1/60 s steps -- and
    // after only 0.0088 s at 5 degrees, inside the very first.
    for (const double a : {5.0, 30.0, 60.0})
        EXPECT_NEAR(*rangeAtAngle(vacuumLaunch(0.5, 0.0), a), vacuumRange(0.5, a, 0.0), 1e-12) << a;
}

TEST(RangeChart, AFlightThatDoesNotLandInTimeHasNoRange)
{
    RangeLaunch launch = vacuumLaunch(100.0, 0.0);
    launch.maxTimeS = 12.0; // at 100 m/s, 30 degrees lands after 10.2 s, 60 degrees after 17.7 s
    const RangeChart chart = rangeChart(launch, 0.0, 90.0, 30.0);
    ASSERT_EQ(chart.rangesM.size(), 4u);
    EXPECT_TRUE(chart.rangesM[1]);  // 30 degrees
    EXPECT_FALSE(chart.rangesM[2]); // 60 degrees
    EXPECT_FALSE(chart.rangesM[3]); // 90 degrees
    EXPECT_EQ(*chart.rangesM[0], 0.0);
}

TEST(RangeChart, GridEndsAtToAndRejectsBadInput)
{
    const RangeChart chart = rangeChart(vacuumLaunch(10.0, 0.0), -90.0, 90.0, 0.1);
    EXPECT_EQ(chart.anglesDeg.size(), 1801u);
    EXPECT_EQ(chart.anglesDeg.back(), 90.0);
    const RangeChart uneven = rangeChart(vacuumLaunch(10.0, 0.0), 0.0, 10.0, 3.0);
    EXPECT_EQ(uneven.anglesDeg, (std::vector<double>{0.0, 3.0, 6.0, 9.0}));
    const RangeChart single = rangeChart(vacuumLaunch(10.0, 0.0), 30.0, 30.0, 1.0);
    ASSERT_EQ(single.anglesDeg.size(), 1u);
    EXPECT_EQ(*single.bestAngleDeg, 30.0);

    EXPECT_THROW(rangeChart(vacuumLaunch(10.0, 0.0), 10.0, 0.0, 1.0), std::invalid_argument);
    EXPECT_THROW(rangeChart(vacuumLaunch(10.0, 0.0), -91.0, 0.0, 1.0), std::invalid_argument);
    EXPECT_THROW(rangeChart(vacuumLaunch(10.0, 0.0), 0.0, 90.0, 0.0), std::invalid_argument);
    EXPECT_THROW(rangeChart(vacuumLaunch(10.0, 0.0), -90.0, 90.0, 1e-4), std::invalid_argument);
    EXPECT_THROW(rangeChart(vacuumLaunch(10.0, -1.0), 0.0, 90.0, 1.0), std::invalid_argument);
    EXPECT_THROW(rangeChart(vacuumLaunch(NAN, 0.0), 0.0, 90.0, 1.0), std::invalid_argument);
}

} // namespace
} // namespace abalike
