#pragma once

#include <abalike/level/LevelDef.hpp>

namespace abalike
{

/// Two levels a player would call the same layout. layoutDistance's occupancy grid calls them different when the
/// same parts stand a few tenths of a metre further apart; this pairs bodies instead. Each block, pig and terrain
/// piece of one level is paired with an unpaired body of the other of the same shape and size (within kTwinSizeShare;
/// materials aside), within kTwinSidewaysM sideways and kTwinVerticalM up or down, both levels counted from their
/// leftmost body's centre. tools/layout-twins is the same measure for a folder of level files.
inline constexpr double kTwinSidewaysM = 1.0;
inline constexpr double kTwinVerticalM = 0.3;
/// Sizes this close (a share of the larger) look the same: a plank 2.6 m or 2.8 m long is the same plank to the eye.
inline constexpr double kTwinSizeShare = 0.1;
/// Levels whose twin share reaches this are twins.
inline constexpr double kTwinShare = 0.9;

/// The smaller of the two shares of bodies that found a partner (a's in b, b's in a): 1 when every body of each has
/// one, 0 when none has (or either level has no bodies).
double layoutTwinShare(const LevelDef& a, const LevelDef& b);

} // namespace abalike
