#include <abalike/level/SlingshotBand.hpp>

#include <algorithm>
#include <cmath>

namespace abalike
{

SlingshotBand::SlingshotBand(const BandDef& band, double birdMassKg, double speedCapMps)
    : m_band(band), m_massKg(birdMassKg), m_speedCapMps(speedCapMps)
{
}

double SlingshotBand::fullPullSpeedMps() const
{
    // Bird and band share E = 1/2 F_max x_max: 1/2 (m + m_b) v0^2 = E.
    return std::sqrt(m_band.maxForceN * m_band.maxPullM / (m_massKg + m_band.bandMassKg));
}

double SlingshotBand::maxSpeedMps() const
{
    return std::min(fullPullSpeedMps(), m_speedCapMps);
}

BandPull SlingshotBand::atFraction(double fraction) const
{
    BandPull pull;
    pull.fraction = std::clamp(fraction, 0.0, 1.0);
    pull.pullM = pull.fraction * m_band.maxPullM;
    pull.forceN = pull.fraction * m_band.maxForceN;
    pull.energyJ = 0.5 * pull.forceN * pull.pullM;
    const double bandSpeed = pull.fraction * fullPullSpeedMps(); // x sqrt(k / (m + m_b)) is linear in the pull
    pull.capped = bandSpeed > m_speedCapMps;
    pull.speedMps = std::min(bandSpeed, m_speedCapMps);
    // The shares of E, written so that a massless band gives the bird exactly E; the cap's speed gives it less.
    pull.birdEnergyJ = pull.capped ? 0.5 * m_massKg * pull.speedMps * pull.speedMps : pull.energyJ * birdShare();
    pull.bandEnergyJ = pull.energyJ * (m_band.bandMassKg / (m_massKg + m_band.bandMassKg));
    return pull;
}

BandPull SlingshotBand::forSpeed(double speedMps) const
{
    const double full = fullPullSpeedMps();
    BandPull pull = atFraction(full > 0.0 ? speedMps / full : 0.0);
    pull.speedMps = std::clamp(speedMps, 0.0, maxSpeedMps());
    pull.birdEnergyJ = 0.5 * m_massKg * pull.speedMps * pull.speedMps;
    return pull;
}

} // namespace abalike
