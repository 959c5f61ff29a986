// The aim readout's text: the band's pull, force, stored energy and launch speed, with units.
#include "render/AimReadout.hpp"

#include <gtest/gtest.h>

namespace abalike::app
{
namespace
{

TEST(AimReadout, ShowsPullForceEnergyAndSpeedWithUnits)
{
    // The teacher's example: a 1 200 N band with a 2 m full pull, drawn 1.6 m with the 4 kg red bird.
    SlingshotDef sling;
    sling.maxForceN = 1200.0;
    const SlingshotBand band(sling, 4.0, 864.0);
    const AimReadout aim = aimReadout(band, 30.0, band.atFraction(0.8));
    EXPECT_EQ(aimSummary(aim), "30.0\u00B0 \u00B7 pull 1.60 m \u00B7 F 960 N \u00B7 E 768 J \u00B7 v\u2080 19.6 m/s");
    EXPECT_EQ(aimLesson(aim), "F = k x,  E = \u00BD F x,  v\u2080 = \u221A(2E / m) with m = 4.0 kg");
    EXPECT_DOUBLE_EQ(aim.maxPullM, 2.0);
    EXPECT_DOUBLE_EQ(aim.maxForceN, 1200.0);
}

TEST(AimReadout, ASmallPullKeepsTwoSignificantDigits)
{
    // The teacher's finding: "E 0 J" at a 2 % pull of the default band, which stores 0.72 J there.
    const SlingshotBand band(SlingshotDef{}, 4.0, 864.0);
    const AimReadout aim = aimReadout(band, 45.0, band.atFraction(0.02));
    EXPECT_EQ(aimSummary(aim), "45.0\u00B0 \u00B7 pull 0.04 m \u00B7 F 36 N \u00B7 E 0.72 J \u00B7 v\u2080 0.60 m/s");
}

TEST(AimReadout, SaysWhenTheCapSetTheSpeed)
{
    SlingshotDef sling;
    sling.maxForceN = 1.0e6;
    const SlingshotBand band(sling, 1.5, 864.0);
    const AimReadout aim = aimReadout(band, 0.0, band.atFraction(1.0));
    EXPECT_NE(aimLesson(aim).find("capped at 864 m/s"), std::string::npos) << aimLesson(aim);
    EXPECT_NE(aimSummary(aim).find("v\u2080 864.0 m/s"), std::string::npos) << aimSummary(aim);
}

} // namespace
} // namespace abalike::app
