#pragma once

#include <span>
#include <string_view>

namespace abalike
{

/// A world the sandbox offers: its surface gravity and the density of its air there. A preset sets both, so that
/// "Mars" does not keep Earth's air.
struct GravityPreset
{
    std::string_view name;
    double gravity;    ///< m/s^2
    double airDensity; ///< kg/m^3 at the surface; 0: no air (and so no wind)
};

/// Earth 9.81 m/s^2 and 1.2 kg/m^3 (sea level, the levels' defaults), Moon 1.62 and none, Mars 3.71 and 0.020, Titan
/// 1.35 and 5.3, Jupiter 24.79 and 0.16 (at the 1 bar level, the "surface" of a gas giant): NASA's planetary fact
/// sheets, to the digits the campaign levels use.
std::span<const GravityPreset> gravityPresets();

} // namespace abalike
