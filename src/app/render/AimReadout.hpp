#pragma once

#include <abalike/level/SlingshotBand.hpp>
#include <string>

namespace abalike::app
{

/// The numbers behind the current aim, shown as a small physics lesson: the band's pull, force and stored energy,
/// the bird's share of it and the launch speed v0 = sqrt(2 E / (m + m_b)) they give the bird.
struct AimReadout
{
    double angleDeg = 0.0;
    double speedMps = 0.0; ///< the launch speed (pull.speedMps)
    BandPull pull;
    double massKg = 0.0;
    double maxPullM = 0.0;   ///< the slingshot's full pull
    double maxForceN = 0.0;  ///< the band's force at full pull
    double bandMassKg = 0.0; ///< the band's mass moving with the bird (0: a massless band)
};

/// The readout of a pull of the current bird's band.
AimReadout aimReadout(const SlingshotBand& band, double angleDeg, const BandPull& pull);

/// One line of the aim's numbers with units: "30.0° · pull 1.60 m · F 6480 N · E 5184 J · v₀ 24.0 m/s".
std::string aimSummary(const AimReadout& aim);
/// How the numbers follow from each other: "F = k x,  E = ½ F x,  v₀ = √(2E / (m + m_b))" ("v₀ = √(2E / m) with
/// m = 4.0 kg" for a massless band).
std::string aimLesson(const AimReadout& aim);
/// Where E goes: "bird (4.0 kg) 1152 J = 22 % of E,  band (14 kg) 4032 J"; empty for a massless band, which gives the
/// bird all of it.
std::string aimShare(const AimReadout& aim);

} // namespace abalike::app
