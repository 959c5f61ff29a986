#pragma once

namespace abalike
{

/// Highest geometric altitude the standard atmosphere covers (m): the top of its seventh layer (84 852 m geopotential).
inline constexpr double kMaxStandardAtmosphereAltitudeM = 86000.0;

/// Air density (kg/m^3) at a geometric altitude above sea level, 0 to kMaxStandardAtmosphereAltitudeM, by the
/// U.S. Standard Atmosphere 1976 (the same as the ICAO standard atmosphere up to 32 km): seven layers of constant
/// temperature lapse rate from 288.15 K and 101 325 Pa at sea level, hydrostatic pressure in each, rho = p / (R T).
/// 1.2250 at sea level, 0.7364 at 5 km, 0.3648 at 11 km. (PhET's Projectile Motion uses NASA Glenn's
/// three-formula fit of the same atmosphere, which agrees with it to about 0.5 % below 5 km.)
/// Throws std::invalid_argument outside the range or for a non-finite altitude.
double standardAtmosphereDensity(double altitudeM);

} // namespace abalike
