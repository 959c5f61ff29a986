#include <abalike/level/SlingshotBand.hpp>

#include <algorithm>
#include <cmath>

namespace abalike
{

SlingshotBand::SlingshotBand(const SlingshotDef& slingshot, double birdMassKg, double speedCapMps)
    : m_maxForceN(slingshot.maxForceN), m_maxPullM(slingshot.maxPullM), m_massKg(birdMassKg), m_speedCapMps(speedCapMps)
{
}

double SlingshotBand::fullPullSpeedMps() const
{
    // v0 = sqrt(2 E / m) with E = 1/2 F_max x_max.
    return std::sqrt(m_maxForceN * m_maxPullM / m_massKg);
}

double SlingshotBand::maxSpeedMps() const
{
    return std::min(fullPullSpeedMps(), m_speedCapMps);
}

BandPull SlingshotBand::atFraction(double fraction) const
{
    BandPull pull;
    pull.fraction = std::clamp(fraction, 0.0, 1.0);
    pull.pullM = pull.fraction * m_maxPullM;
    pull.forceN = pull.fraction * m_maxForceN;
    pull.energyJ = 0.5 * pull.forceN * pull.pullM;
    const double bandSpeed = pull.fraction * fullPullSpeedMps(); // sqrt(2 E / m) is linear in the pull
    pull.capped = bandSpeed > m_speedCapMps;
    pull.speedMps = std::min(bandSpeed, m_speedCapMps);
    return pull;
}

BandPull SlingshotBand::forSpeed(double speedMps) const
{
    const double full = fullPullSpeedMps();
    BandPull pull = atFraction(full > 0.0 ? speedMps / full : 0.0);
    pull.speedMps = std::clamp(speedMps, 0.0, maxSpeedMps());
    return pull;
}

} // namespace abalike
