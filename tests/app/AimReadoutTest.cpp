// The aim readout's text: the band's pull, force, stored energy and launch speed, with units.
#include "render/AimReadout.hpp"

#include <gtest/gtest.h>

namespace abalike::app
{
namespace
{

TEST(AimReadout, ShowsPullForceEnergyAndSpeedWithUnits)
{
    // The teacher's example: a massless 1 200 N band with a 2 m full pull, drawn 1.6 m with the 4 kg red bird.
    const SlingshotBand band(BandDef{1200.0, 2.0, 0.0}, 4.0, 864.0);
    const AimReadout aim = aimReadout(band, 30.0, band.atFraction(0.8));
    EXPECT_EQ(aimSummary(aim), "30.0\u00B0 \u00B7 pull 1.60 m \u00B7 F 960 N \u00B7 E 768 J \u00B7 v\u2080 19.6 m/s");
    EXPECT_EQ(aimLesson(aim), "F = k x,  E = \u00BD F x,  v\u2080 = \u221A(2E / m) with m = 4.0 kg");
    EXPECT_EQ(aimShare(aim), "") << "a massless band gives the bird all of E: nothing to share";
    EXPECT_DOUBLE_EQ(aim.maxPullM, 2.0);
    EXPECT_DOUBLE_EQ(aim.maxForceN, 1200.0);
}

TEST(AimReadout, ASmallPullKeepsTwoSignificantDigits)
{
    // The teacher's finding: "E 0 J" at a 2 % pull of the band, which stores 3.24 J there, 0.72 J of it the bird's.
    const SlingshotBand band(BandDef{}, 4.0, 864.0);
    const AimReadout aim = aimReadout(band, 45.0, band.atFraction(0.02));
    EXPECT_EQ(aimSummary(aim), "45.0\u00B0 \u00B7 pull 0.04 m \u00B7 F 162 N \u00B7 E 3.2 J \u00B7 v\u2080 0.60 m/s");
    EXPECT_EQ(aimLesson(aim), "F = k x,  E = \u00BD F x,  v\u2080 = \u221A(2E / (m + m_b))");
    EXPECT_EQ(aimShare(aim), "bird (4.0 kg) 0.72 J = 22 % of E,  band (14 kg) 2.5 J");
}

TEST(AimReadout, SaysWhenTheCapSetTheSpeed)
{
    const SlingshotBand band(BandDef{1.0e6, 2.0, 0.0}, 1.5, 864.0); // a massless band: 1 155 m/s uncapped
    const AimReadout aim = aimReadout(band, 0.0, band.atFraction(1.0));
    EXPECT_NE(aimLesson(aim).find("capped at 864 m/s"), std::string::npos) << aimLesson(aim);
    EXPECT_NE(aimSummary(aim).find("v\u2080 864.0 m/s"), std::string::npos) << aimSummary(aim);
}

} // namespace
} // namespace abalike::app
