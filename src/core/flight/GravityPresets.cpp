#include <abalike/flight/GravityPresets.hpp>

#include <array>

namespace abalike
{

std::span<const GravityPreset> gravityPresets()
{
    static constexpr std::array<GravityPreset, 5> kPresets{{
        {"Earth", 9.81},
        {"Moon", 1.62},
        {"Mars", 3.71},
        {"Titan", 1.35},
        {"Jupiter", 24.79},
    }};
    return kPresets;
}

} // namespace abalike
