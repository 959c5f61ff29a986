#pragma once

#include <numbers>

namespace abalike
{

/// Degrees to radians, as one factor (angles are degrees at the interfaces and radians inside).
inline constexpr double kDegToRad = std::numbers::pi / 180.0;

} // namespace abalike
