#pragma once

#include <abalike/level/LevelDef.hpp>

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace abalike
{

class Catalog;

/// One problem found in a level file.
struct LevelIssue
{
    std::string file;
    int line = 0;        ///< 1-based; 0 when unknown
    int column = 0;      ///< 1-based; 0 when unknown
    std::string pointer; ///< JSON pointer of the offending value, e.g. /blocks/3/material
    std::string message;

    /// "FILE:LINE:COL: error: /json/pointer: message"
    std::string format() const;
};

/// Thrown when a level cannot be loaded; holds every problem found, not just the first.
class LevelLoadError : public std::runtime_error
{
public:
    explicit LevelLoadError(std::vector<LevelIssue> issues);
    const std::vector<LevelIssue>& issues() const { return m_issues; }

private:
    std::vector<LevelIssue> m_issues;
};

/// Reads and parses a level file. Throws LevelLoadError.
LevelDef loadLevel(const std::string& path, const Catalog& catalog);

/// The .json files directly in a folder, sorted by name (levels/parts/, levels/endless/); none when it cannot be
/// read.
std::vector<std::string> levelFilesIn(const std::string& folder);

/// Parses level JSON text; fileName is used in messages. Throws LevelLoadError.
LevelDef parseLevel(std::string_view text, const std::string& fileName, const Catalog& catalog);

/// A level read for editing: what loadLevel throws for (syntax, structure, values) it throws too, but the geometry
/// checks' problems (overlaps, bounds, reach, the slingshot) are returned, so an editor can open the level with
/// them marked on the objects.
struct EditableLevel
{
    LevelDef level;
    std::vector<LevelIssue> geometryIssues;
};

/// Reads a level file for editing. Throws LevelLoadError for everything but geometry problems.
EditableLevel loadLevelForEditing(const std::string& path, const Catalog& catalog);

/// Parses level JSON text for editing; fileName is used in messages. Throws LevelLoadError.
EditableLevel parseLevelForEditing(std::string_view text, const std::string& fileName, const Catalog& catalog);

/// The checks loadLevel makes of a level's values (types, ranges, names, required fields), without geometry, on a
/// level in memory; issues have pointers and no line or column. Empty when the level would load.
std::vector<LevelIssue> checkLevelFields(const LevelDef& level, const Catalog& catalog);

/// The geometry checks loadLevel runs (overlaps, world bounds, reach, the slingshot, the reference shot), on a level
/// in memory: each issue names its object by JSON pointer (/blocks/3) and has no line or column.
std::vector<LevelIssue> checkLevelGeometry(const LevelDef& level, const Catalog& catalog);

/// One episode of a campaign manifest.
struct CampaignEpisode
{
    std::string id;
    std::string title;
    std::vector<std::string> levelPaths; ///< resolved against the manifest's folder
    std::vector<LevelIssue> levelPlaces; ///< where each level is listed in the manifest (file, line, column, pointer)
};

/// True if the file is a JSON object with "episodes" (a campaign manifest) rather than a level; false for anything
/// unreadable or invalid, which the level loader then reports.
bool isCampaignManifest(const std::string& path);

/// The episodes of a campaign manifest (levels/campaign.json), in play order. Throws LevelLoadError.
/// keepGoing: return the entries that could be read despite problems in others (syntax errors still throw).
std::vector<CampaignEpisode> loadCampaignEpisodes(const std::string& manifestPath, bool keepGoing = false);

/// The levels of a campaign manifest, in play order (paths resolved against the manifest's folder).
std::vector<std::string> loadCampaign(const std::string& manifestPath);

} // namespace abalike
