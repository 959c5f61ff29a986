#pragma once

namespace abalike
{

/// The numbers of a slingshot's band (SI units): what a level's slingshot resolves to (levelBand in LevelFlight.hpp).
struct BandDef
{
    double maxForceN = 8100.0; ///< the band's force at full pull (N)
    double maxPullM = 2.0;     ///< full pull (m)
    double bandMassKg = 14.0;  ///< the mass of pouch and rubber that moves with the bird (kg)

    bool operator==(const BandDef&) const = default;
};

/// The numbers of one pull of the slingshot (SI units).
struct BandPull
{
    double fraction = 0.0;    ///< pull as a share of the slingshot's maximum pull, 0 to 1
    double pullM = 0.0;       ///< x: how far the pouch is drawn back
    double forceN = 0.0;      ///< F = k x: the band's force at that pull
    double energyJ = 0.0;     ///< E = 1/2 F x: the work done drawing the band, stored in it
    double birdEnergyJ = 0.0; ///< 1/2 m v0^2: the bird's share, m / (m + m_b) of E (less when the cap set the speed)
    double bandEnergyJ = 0.0; ///< m_b / (m + m_b) of E: what the band's moving mass keeps (the frame absorbs it)
    double speedMps = 0.0;    ///< v0 = x sqrt(k / (m + m_b)), at most the catalog's launch-speed cap
    bool capped = false;      ///< the cap, not the band, set the speed
};

/// The slingshot's band as a linear spring without losses whose pouch and rubber move with the bird as one lumped
/// mass m_b: drawn back x (up to maxPullM) it pulls with F = k x, k = maxForceN / maxPullM, and stores
/// E = 1/2 k x^2 = 1/2 F x; released, bird and band reach the same speed when the band is slack, so
/// v0 = x sqrt(k / (m + m_b)) and the bird takes m / (m + m_b) of E. The moving mass evens the birds out: a bird
/// twice as heavy leaves sqrt((m + m_b) / (2 m + m_b)) as fast, not 1/sqrt(2) (docs/slingshot.md). With m_b = 0 it is
/// the massless band, v0 = sqrt(2 E / m). Launch speed grows linearly with the pull fraction.
class SlingshotBand
{
public:
    /// speedCapMps: the catalog's launch-speed cap (Catalog::maxLaunchSpeedMps), the one cap of the game.
    SlingshotBand(const BandDef& band, double birdMassKg, double speedCapMps);

    /// Spring constant k (N/m).
    double stiffness() const { return m_band.maxForceN / m_band.maxPullM; }
    /// Energy stored at full pull (J).
    double fullEnergyJ() const { return 0.5 * m_band.maxForceN * m_band.maxPullM; }
    /// The share of the stored energy the bird takes, m / (m + m_b).
    double birdShare() const { return m_massKg / (m_massKg + m_band.bandMassKg); }
    /// Launch speed at full pull by the band alone, before the cap (m/s).
    double fullPullSpeedMps() const;
    /// Fastest launch: the full pull's speed, at most the cap.
    double maxSpeedMps() const;
    double maxPullM() const { return m_band.maxPullM; }
    double maxForceN() const { return m_band.maxForceN; }
    double bandMassKg() const { return m_band.bandMassKg; }
    double birdMassKg() const { return m_massKg; }
    const BandDef& def() const { return m_band; }

    /// The pull at a fraction of the maximum (clamped to 0..1).
    BandPull atFraction(double fraction) const;
    /// The smallest pull that launches at speedMps (for a scripted or solver shot given as a speed); a speed the
    /// cap reached is shown at the pull where the band alone reaches it, at most a full pull.
    BandPull forSpeed(double speedMps) const;

private:
    BandDef m_band;
    double m_massKg;
    double m_speedCapMps;
};

} // namespace abalike
