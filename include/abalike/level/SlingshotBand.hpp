#pragma once

#include <abalike/level/LevelDef.hpp>

namespace abalike
{

/// The numbers of one pull of the slingshot (SI units).
struct BandPull
{
    double fraction = 0.0; ///< pull as a share of the slingshot's maximum pull, 0 to 1
    double pullM = 0.0;    ///< x: how far the pouch is drawn back
    double forceN = 0.0;   ///< F = k x: the band's force at that pull
    double energyJ = 0.0;  ///< E = 1/2 F x: the work done drawing the band, stored in it
    double speedMps = 0.0; ///< v0 = sqrt(2 E / m), at most the catalog's launch-speed cap
    bool capped = false;   ///< the cap, not the band, set the speed
};

/// The slingshot's band as a massless linear spring without losses: drawn back x (up to maxPullM) it pulls with
/// F = k x, k = maxForceN / maxPullM, and stores E = 1/2 k x^2 = 1/2 F x; released, it gives all of E to the bird as
/// kinetic energy, so v0 = sqrt(2 E / m). The same pull gives every bird the same energy: a bird twice as heavy
/// leaves 1/sqrt(2) as fast (docs/slingshot.md). Launch speed grows linearly with the pull fraction.
class SlingshotBand
{
public:
    /// speedCapMps: the catalog's launch-speed cap (Catalog::maxLaunchSpeedMps), the one cap of the game.
    SlingshotBand(const SlingshotDef& slingshot, double birdMassKg, double speedCapMps);

    /// Spring constant k (N/m).
    double stiffness() const { return m_maxForceN / m_maxPullM; }
    /// Energy stored at full pull (J).
    double fullEnergyJ() const { return 0.5 * m_maxForceN * m_maxPullM; }
    /// Launch speed at full pull by the band alone, before the cap (m/s).
    double fullPullSpeedMps() const;
    /// Fastest launch: the full pull's speed, at most the cap.
    double maxSpeedMps() const;
    double maxPullM() const { return m_maxPullM; }
    double maxForceN() const { return m_maxForceN; }
    double birdMassKg() const { return m_massKg; }

    /// The pull at a fraction of the maximum (clamped to 0..1).
    BandPull atFraction(double fraction) const;
    /// The smallest pull that launches at speedMps (for a scripted or solver shot given as a speed); a speed the
    /// cap reached is shown at the pull where the band alone reaches it, at most a full pull.
    BandPull forSpeed(double speedMps) const;

private:
    double m_maxForceN;
    double m_maxPullM;
    double m_massKg;
    double m_speedCapMps;
};

} // namespace abalike
