#pragma once

#include <map>
#include <string>
#include <vector>

namespace abalike
{

/// One renumbering of a campaign's levels: when the balance reorders the levels of an episode, each moved level's
/// file and id are renamed to its new place ("1-7" becomes "1-4"), and the manifest keeps what each old id became,
/// so that progress saved under the old ids follows its levels (renumberProgress).
struct Renumbering
{
    int numbering = 2;                         ///< the numbering this step leads to (the first is 2)
    std::map<std::string, std::string> newIds; ///< old id -> new id; an id not here kept its name

    bool operator==(const Renumbering&) const = default;
};

/// The history of a campaign's level ids: its current numbering (1 for a campaign never renumbered) and the steps
/// that led there, oldest first (a manifest's "renumbered").
struct LevelNumbering
{
    std::vector<Renumbering> steps;

    int current() const { return steps.empty() ? 1 : steps.back().numbering; }
    /// What a level id of numbering `since` is called now.
    std::string idNow(const std::string& id, int since) const;

    bool operator==(const LevelNumbering&) const = default;
};

/// The "renumbered" history of a campaign manifest (levels/campaign.json). Throws LevelLoadError, located, when it
/// is malformed: numberings not rising by one from 2, an id renamed twice in one step, two ids given one new name.
LevelNumbering loadLevelNumbering(const std::string& manifestPath);

} // namespace abalike
