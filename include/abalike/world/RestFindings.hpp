#pragma once

#include <abalike/level/LevelDef.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/world/Catalog.hpp>
#include <abalike/world/RestCheck.hpp>
#include <optional>
#include <string>
#include <vector>

namespace abalike
{

/// Why one body of a level did not stay where it was built, in the designer's terms, and the fix where one is
/// clear: what `check` reports in `errors[]` for a level that fails the rest check.
struct RestFinding
{
    std::string pointer; ///< the body in the level file: /blocks/3 or /pigs/0
    std::string what;    ///< "floats 1.0 cm above block 3 (wood)", "overlaps the ground by 7 mm", ...
    std::string fix;     ///< "set y = 0.25"; empty when no single change is clear
    /// The y that rests the body on its support (for floating or overlapping bodies within kMaxSnapM); what
    /// `check --fix` writes.
    std::optional<double> snapY;
    /// The verified fix as numbers (the body's new y, x or angle_deg): what `check --fix` writes. Set only when the
    /// rest check, run with every finding's fix made, found this body and its consequences standing.
    std::optional<double> fixY;
    std::optional<double> fixX;
    std::optional<double> fixAngleDeg;
    /// A leaning stack's verified fix: the x to set for this body and each of its consequences (straight up over
    /// what it stands on).
    std::optional<double> groupX;
    /// A floating or sunk body's verified fix that carries its load: the bodies on it (movedWith) move by this much
    /// in y with it.
    std::optional<double> groupDy;
    std::vector<std::string> movedWith;
    /// The bodies that only follow this one (they start moving after it, touching it): fixing it fixes them.
    std::vector<std::string> consequences;

    /// "what; fix" (or just "what").
    std::string message() const;

    /// `check --fix` moves bodies at most this far.
    static constexpr double kMaxSnapM = 0.02;
};

/// The designed bottom of a body and what is right under it, from the level as written (no simulation).
struct SupportGap
{
    std::string support;       ///< "block 3 (wood)", "the ground", "terrain 1"; empty when nothing is under it
    double gapM = 0.0;         ///< bottom of the body minus top of the support: > 0 floats, < 0 overlaps
    double supportLeftM = 0.0; ///< the support's horizontal extent under the body
    double supportRightM = 0.0;
    /// A block of a slippery material (friction below kSlipperyFriction, as ice): a body on it may slide off.
    bool supportIsSlippery = false;
    std::string supportMaterial; ///< the support block's material; empty for the ground and terrain
    double supportFriction = 0.0;

    static constexpr double kSlipperyFriction = 0.2;
};

/// A distance as the findings write it: "5.0 mm" under a centimetre, "25.0 cm" under a metre, "7.00 m" from there.
std::string distanceInWords(double metres);

/// What is right under a block (blocks[index]) or a pig (pigs[index]) as designed.
SupportGap supportUnder(const LevelDef& level, const Catalog& catalog, bool pig, int index);

/// Where a body's bottom would rest: from fromM to toM along x, its bottom and top at bottomM and topM.
struct SupportSpan
{
    double fromM = 0.0;
    double toM = 0.0;
    double bottomM = 0.0;
    double topM = 0.0;
    int skipBlock = -1; ///< the body itself, when it is a block
};

/// What is right under a span, as supportUnder finds it under a body's bottom (a flat body's span is its width, a
/// round one's its centre).
SupportGap supportUnderSpan(const LevelDef& level, const Catalog& catalog, const SupportSpan& span);

/// One finding per body that moved more than the report's tolerance or took damage.
std::vector<RestFinding> restFindings(const LevelDef& level, const Catalog& catalog, const RestReport& report);

/// The findings of a rest report as issues of the level file: located (line, column) when the file can be read,
/// each message "what; fix". Empty when the report passed.
std::vector<LevelIssue> restIssues(const LevelDef& level, const Catalog& catalog, const RestReport& report,
                                   const std::string& file);

} // namespace abalike
