#include <abalike/flight/GravityPresets.hpp>

#include <array>

namespace abalike
{

std::span<const GravityPreset> gravityPresets()
{
    static constexpr std::array<GravityPreset, 5> kPresets{{
        {"Earth", 9.81, 1.2},
        {"Moon", 1.62, 0.0},
        {"Mars", 3.71, 0.020},
        {"Titan", 1.35, 5.3},
        {"Jupiter", 24.79, 0.16},
    }};
    return kPresets;
}

} // namespace abalike
