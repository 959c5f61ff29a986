#pragma once

#include <span>
#include <string_view>

namespace abalike
{

/// Surface gravity of a body the sandbox offers.
struct GravityPreset
{
    std::string_view name;
    double gravity; ///< m/s^2
};

/// Earth (9.81, the levels' default), Moon 1.62, Mars 3.71, Titan 1.35, Jupiter 24.79 (cloud tops): NASA's planetary
/// fact sheets, to the digits the campaign levels use.
std::span<const GravityPreset> gravityPresets();

} // namespace abalike
