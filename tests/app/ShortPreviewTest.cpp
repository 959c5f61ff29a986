// Game mode's short preview: the climb to the top of the arc, never less than half a second.
#include "render/OverlayRenderer.hpp"

#include <abalike/flight/Prediction.hpp>
#include <cmath>
#include <gtest/gtest.h>

using namespace abalike;
using namespace abalike::app;

namespace
{
PredictedFlight flightAt(double speedMps, double angleDeg)
{
    PredictionLimits limits;
    limits.stopOnLanding = true;
    return predictFlight(FlightModel{}, {}, launchState(0.0, 0.0, speedMps, angleDeg), limits);
}
} // namespace

TEST(ShortPreview, ShowsTheClimbToTheTopOfTheArc)
{
    // 30 m/s at 45 degrees climbs for v sin a / g = 2.16 s: 130 steps of 1/60 s, not the 30 of half a second.
    const PredictedFlight steep = flightAt(30.0, 45.0);
    const std::size_t dots = shortPreviewDots(steep);
    const double apexS = 30.0 * std::sin(M_PI / 4.0) / 9.81;
    EXPECT_NEAR(steep.path[dots - 1].timeS, apexS, 1.0 / 60.0);
    EXPECT_LT(dots, steep.path.size()) << "not the landing";
}

TEST(ShortPreview, NeverLessThanHalfASecond)
{
    // Aimed level or down there is no climb: half a second of dots still shows the direction.
    EXPECT_EQ(shortPreviewDots(flightAt(20.0, 0.0)), 30u);
    EXPECT_EQ(shortPreviewDots(flightAt(20.0, -20.0)), 30u);
    // A flight shorter than that is shown whole.
    const PredictedFlight lob = flightAt(1.0, 10.0);
    EXPECT_EQ(shortPreviewDots(lob), lob.path.size());
}
