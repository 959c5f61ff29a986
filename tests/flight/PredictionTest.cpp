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
    EXPECT_NEAR(flight.path.back().s[0] / expected, 1.0, 1e-12);
    EXPECT_NEAR(flight.path.back().t, 2.0 * 20.0 * std::sin(M_PI / 4) / 9.81, 1e-12);
    EXPECT_NEAR(flight.maxHeightM, 20.0 * 20.0 * 0.5 / (2.0 * 9.81), 1e-9); // v^2 sin^2(45) / 2g
}

} // namespace
} // namespace abalike
