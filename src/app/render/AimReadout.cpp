#include "render/AimReadout.hpp"

#include "render/TextFormat.hpp"

namespace abalike::app
{

AimReadout aimReadout(const SlingshotBand& band, double angleDeg, const BandPull& pull)
{
    AimReadout readout;
    readout.angleDeg = angleDeg;
    readout.speedMps = pull.speedMps;
    readout.pull = pull;
    readout.massKg = band.birdMassKg();
    readout.maxPullM = band.maxPullM();
    readout.maxForceN = band.maxForceN();
    return readout;
}

std::string aimSummary(const AimReadout& aim)
{
    const char* dot = " \u00B7 ";
    return formatFixed(aim.angleDeg, 1) + "\u00B0" + dot + "pull " + formatFixed(aim.pull.pullM, 2) + " m" + dot +
           "F " + formatFixed(aim.pull.forceN, 0) + " N" + dot + "E " + formatFixed(aim.pull.energyJ, 0) + " J" + dot +
           "v\u2080 " + formatFixed(aim.speedMps, 1) + " m/s";
}

std::string aimLesson(const AimReadout& aim)
{
    // The band is a spring: F = k x, its stored energy the area under F, all of it given to the bird.
    std::string text =
        "F = k x,  E = \u00BD F x,  v\u2080 = \u221A(2E / m) with m = " + formatFixed(aim.massKg, 1) + " kg";
    if (aim.pull.capped)
        text += ", capped at " + formatFixed(aim.speedMps, 0) + " m/s";
    return text;
}

} // namespace abalike::app
