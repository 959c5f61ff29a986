#pragma once

#include <abalike/level/LevelDef.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/level/LevelNumbering.hpp>
#include <cstddef>
#include <map>
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
    /// What progress is saved under: the level's id for the bundled campaign, "PACK/ID" for a level pack's. When a
    /// reorder renames ids, the manifest's renumbering carries saved stars to the new keys (renumberProgress).
    std::string key;
    std::string pack; ///< the level pack's name (its folder); empty for the bundled campaign
    /// What the player calls it: its episode and its place there, from 1 ("2-6" for the sixth level of episode 2), on
    /// its tile, in its title and for `play --level`. Follows the order; the bundled campaign's ids follow it too
    /// (tools/renumber-levels), a level pack's may differ.
    std::string number;

    /// The name `play --level` takes: the number, "PACK/NUMBER" for a level pack's.
    std::string levelArgument() const { return pack.empty() ? number : pack + "/" + number; }
};

/// A campaign manifest with every level it lists loaded, in play order.
struct Campaign
{
    std::string manifestPath;
    std::vector<CampaignEpisode> episodes;
    std::vector<CampaignLevel> levels;
    /// How each part's level ids were renumbered: "" for the manifest's own levels, a level pack's by its name.
    std::map<std::string, LevelNumbering> numberings;

    /// Progress keys in play order (CampaignLevel::key: the level id, or PACK/ID in a level pack).
    std::vector<std::string> levelIds() const;
    /// Index into levels of the level with that progress key.
    std::optional<std::size_t> indexOf(const std::string& levelKey) const;
    /// Index into levels of the level `play --level` names (CampaignLevel::levelArgument).
    std::optional<std::size_t> indexOfNumber(const std::string& levelArgument) const;
    /// Every level's levelArgument, in play order.
    std::vector<std::string> levelArguments() const;
};

/// Loads a manifest and every level it lists. Throws LevelLoadError with the problems of every file that does not
/// load, so a designer sees them all at once.
Campaign loadCampaignLevels(const std::string& manifestPath, const Catalog& catalog);

/// Adds a level pack after the campaign's episodes: a folder with a campaign.json (the same manifest format), its
/// levels keyed "NAME/ID" where NAME is the folder's name, its episodes titled "NAME: TITLE". Throws LevelLoadError
/// (every problem of the pack) and leaves the campaign unchanged then.
void appendLevelPack(Campaign& campaign, const std::string& packFolder, const Catalog& catalog);

/// The level packs installed in a folder (the user data folder's packs/): its sub-folders that hold a
/// campaign.json, by name.
std::vector<std::string> installedLevelPacks(const std::string& packsFolder);

} // namespace abalike
