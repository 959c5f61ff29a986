#pragma once

#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Catalog.hpp>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace abalike
{

/// An outcome claim's fan: its shot and the aims around it, 1 degree and 0.5 m/s apart (3 x 3).
inline constexpr int kOutcomeFanAims = 9;
inline constexpr double kOutcomeFanAngleStepDeg = 1.0;
inline constexpr double kOutcomeFanSpeedStepMps = 0.5;
/// How long after its launch each aim of the fan is watched: a tower takes a few seconds to fall onto the next.
inline constexpr double kOutcomeWatchS = 8.0;

/// A cannot-break claim's grid of first shots, each with the fan around it: these angles at these shares of the
/// bird's full-pull speed.
inline constexpr double kCannotBreakAnglesDeg[] = {0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0};
inline constexpr double kCannotBreakPulls[] = {0.7, 0.85, 1.0};
/// When a cannot-break claim's bird uses its ability, as shares of its time to the first contact without it: halfway
/// (a split or a boost well before the structure), just before (the boost's full speed, the split's tight spread, the
/// egg over what it reaches) and at the contact (the blast on what it struck). Two of them are the solver's moments.
inline constexpr double kCannotBreakAbilityShares[] = {0.5, 0.9, 1.0};

/// A full-pull-reach claim's angles: every one from 0 up to 90 degrees, this far apart.
inline constexpr double kReachAnglesStepDeg = 0.5;

/// A claim's comparison, split: LEFT OP RIGHT (levels/README.md, "Claims").
struct ClaimParts
{
    std::string_view left;
    std::string_view op; ///< "<", ">", "<=" or ">="
    std::string_view right;
    std::size_t rightOffset = 0; ///< where right starts in the claim
};

/// Splits "EXPRESSION OP EXPRESSION". Returns nullopt and says why in error when there is not exactly one
/// comparison with an expression on each side.
std::optional<ClaimParts> splitClaim(std::string_view holds, std::string& error);

/// Syntax, names and arguments of a claim, without computing (cheap enough for the level reader): the problems,
/// each with the character (from 0) where it starts.
std::vector<std::pair<std::size_t, std::string>> checkClaim(std::string_view holds, const LevelDef& level,
                                                            const Catalog& catalog);

/// A claim computed for its level.
struct ClaimResult
{
    bool holds = false;
    double left = 0.0;
    double right = 0.0;
    std::string message; ///< "best_angle:red = 34.0 is not < calm_best_angle:red = 39.4", or why it cannot be computed
    int aimsThatDo = 0;  ///< an outcome: how many of the fan's aims make it happen
};

/// Computes the claim for the level: a comparison from the level's values; an outcome by playing the level's first
/// bird at each aim of the fan around its shot (the speed kept to what the slingshot gives) for kOutcomeWatchS; a
/// cannot-break claim by playing every bird the level has over the grid (kCannotBreakAnglesDeg x kCannotBreakPulls)
/// and the fan around each shot, its ability at each of kCannotBreakAbilityShares and unused, each for
/// kOutcomeWatchS: it holds when no block of the material breaks (by a bird's hit, with "cause": "bird") in any of
/// them; a full-pull-reach claim by playing the level's first bird at full pull at every angle (kReachAnglesStepDeg
/// apart) until its first contact: it holds when every aim whose first contact is a pig in the range lies within the
/// claim's degrees of the best angle and the aim nearest the best angle is one of them.
ClaimResult evaluateClaim(const ClaimDef& claim, const LevelDef& level, const Catalog& catalog);

} // namespace abalike
