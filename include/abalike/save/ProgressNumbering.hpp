#pragma once

#include <abalike/level/Campaign.hpp>
#include <abalike/save/Progress.hpp>

namespace abalike
{

/// Brings progress saved under an earlier numbering of a campaign part's levels ("" the bundled campaign, else a
/// level pack's name) to its current one: every record and unlock follows its level to the level's new id, so a
/// player keeps their stars when the balance reorders an episode. Two records that end on one id keep the better
/// score and the more stars. Returns true when the progress changed.
bool renumberProgress(Progress& progress, const std::string& part, const LevelNumbering& numbering);

/// renumberProgress for every part of the campaign (the bundled levels and each level pack).
bool renumberProgress(Progress& progress, const Campaign& campaign);

} // namespace abalike
