#pragma once

namespace abalike
{

/// The launch angles the solver and the model player try: down to -10 degrees (a slingshot on a cliff shoots
/// down) and up to 80.
inline constexpr double kAimMinAngleDeg = -10.0;
inline constexpr double kAimMaxAngleDeg = 80.0;

} // namespace abalike
