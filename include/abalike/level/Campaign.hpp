#pragma once

#include <abalike/level/LevelDef.hpp>
#include <abalike/level/LevelIO.hpp>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace abalike
{

class Catalog;

/// One level of a loaded campaign.
struct CampaignLevel
{
    std::string path;        ///< the level file
    std::size_t episode = 0; ///< index into Campaign::episodes
    LevelDef level;
};

/// A campaign manifest with every level it lists loaded, in play order.
struct Campaign
{
    std::string manifestPath;
    std::vector<CampaignEpisode> episodes;
    std::vector<CampaignLevel> levels;

    /// Level ids in play order (what progress is keyed by).
    std::vector<std::string> levelIds() const;
    /// Index into levels of the level with that id.
    std::optional<std::size_t> indexOf(const std::string& levelId) const;
};

/// Loads a manifest and every level it lists. Throws LevelLoadError with the problems of every file that does not
/// load, so a designer sees them all at once.
Campaign loadCampaignLevels(const std::string& manifestPath, const Catalog& catalog);

} // namespace abalike
