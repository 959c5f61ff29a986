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
};

ClaimResult evaluateClaim(const ClaimDef& claim, const LevelDef& level, const Catalog& catalog);

} // namespace abalike
