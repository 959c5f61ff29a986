#include "render/AimReadout.hpp"

#include <algorithm>
#include <cmath>

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
    readout.bandMassKg = band.bandMassKg();
    return readout;
}

namespace
{
/// Enough decimals for two significant digits of a small value: a 2 % pull stores 0.72 J, not "0 J".
std::string readable(double value, int decimals)
{
    const double size = std::abs(value);
    const int needed = size == 0.0 || size >= 10.0 ? 0 : size >= 1.0 ? 1 : 2;
    return formatFixed(value, std::max(decimals, needed));
}
} // namespace

std::string aimSummary(const AimReadout& aim)
{
    const char* dot = " \u00B7 ";
    return formatFixed(aim.angleDeg, 1) + "\u00B0" + dot + "pull " + formatFixed(aim.pull.pullM, 2) + " m" + dot +
           "F " + readable(aim.pull.forceN, 0) + " N" + dot + "E " + readable(aim.pull.energyJ, 0) + " J" + dot +
           "v\u2080 " + readable(aim.speedMps, 1) + " m/s";
}

std::string aimLesson(const AimReadout& aim)
{
    // The band is a spring: F = k x, its stored energy the area under F, shared by the bird and the band's moving
    // mass, which reach the same speed when the band goes slack.
    std::string text = "F = k x,  E = \u00BD F x,  ";
    if (aim.bandMassKg > 0.0)
        text += "v\u2080 = \u221A(2E / (m + m_b))";
    else
        text += "v\u2080 = \u221A(2E / m) with m = " + formatFixed(aim.massKg, 1) + " kg";
    if (aim.pull.capped)
        text += ", capped at " + formatFixed(aim.speedMps, 0) + " m/s";
    return text;
}

std::string aimShare(const AimReadout& aim)
{
    if (aim.bandMassKg <= 0.0)
        return {};
    const double share = aim.massKg / (aim.massKg + aim.bandMassKg);
    return "bird (" + formatFixed(aim.massKg, 1) + " kg) " + readable(aim.pull.birdEnergyJ, 0) +
           " J = " + formatFixed(100.0 * share, 0) + " % of E,  band (" + readable(aim.bandMassKg, 0) + " kg) " +
           readable(aim.pull.bandEnergyJ, 0) + " J";
}

} // namespace abalike::app
