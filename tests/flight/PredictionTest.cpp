#include <abalike/flight/Prediction.hpp>

#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

TEST(Prediction, VacuumRangeMatchesClosedForm)
{
    FlightModel vacuum;
    PredictionLimits limits;
    limits.stopOnLanding = true;
    const PredictedFlight flight = predictFlight(vacuum, {}, launchState(0, 0, 20, 45), limits);
    ASSERT_EQ(flight.end, FlightEnd::Landed);
    const double expected = 20.0 * 20.0 / 9.81;
    EXPECT_NEAR(flight.path.back().state.position.x / expected, 1.0, 1e-12);
    EXPECT_NEAR(flight.path.back().timeS, 2.0 * 20.0 * std::sin(M_PI / 4) / 9.81, 1e-12);
    EXPECT_NEAR(flight.maxHeightM, 20.0 * 20.0 * 0.5 / (2.0 * 9.81), 1e-9); // v^2 sin^2(45) / 2g
}

TEST(Prediction, ASlowLaunchLandsInsideTheFirstStep)
{
    // 0.5 m/s at 30 degrees is back at the launch height after 0.051 s; at 5 degrees after 0.0089 s, inside the first
    // 1/60 s step, whose both ends are at or below the launch height.
    PredictionLimits limits;
    limits.stopOnLanding = true;
    for (const double angle : {5.0, 30.0})
    {
        const PredictedFlight flight = predictFlight(FlightModel{}, {}, launchState(0.0, 1.0, 0.5, angle), limits);
        ASSERT_EQ(flight.end, FlightEnd::Landed) << angle;
        const double rad = angle * 3.141592653589793 / 180.0;
        EXPECT_NEAR(flight.path.back().state.position.x, 0.25 * std::sin(2.0 * rad) / 9.81, 1e-12) << angle;
        EXPECT_EQ(flight.path.back().state.position.y, 1.0);
    }
}

TEST(Prediction, LandsAtAGivenHeight)
{
    PredictionLimits limits;
    limits.stopOnLanding = true;
    limits.landingY = 0.0;
    // From 10 m up at 20 m/s horizontally: down after sqrt(2 h / g).
    const PredictedFlight flight = predictFlight(FlightModel{}, {}, {{0.0, 10.0}, {20.0, 0.0}}, limits);
    ASSERT_EQ(flight.end, FlightEnd::Landed);
    EXPECT_NEAR(flight.path.back().timeS, std::sqrt(20.0 / 9.81), 1e-12);
    EXPECT_NEAR(flight.path.back().state.position.x, 20.0 * std::sqrt(20.0 / 9.81), 1e-11);
}

} // namespace
} // namespace abalike
