#include <abalike/level/Campaign.hpp>

namespace abalike
{

std::vector<std::string> Campaign::levelIds() const
{
    std::vector<std::string> ids;
    ids.reserve(levels.size());
    for (const CampaignLevel& entry : levels)
        ids.push_back(entry.level.id);
    return ids;
}

std::optional<std::size_t> Campaign::indexOf(const std::string& levelId) const
{
    for (std::size_t i = 0; i < levels.size(); ++i)
        if (levels[i].level.id == levelId)
            return i;
    return std::nullopt;
}

Campaign loadCampaignLevels(const std::string& manifestPath, const Catalog& catalog)
{
    Campaign campaign;
    campaign.manifestPath = manifestPath;
    campaign.episodes = loadCampaignEpisodes(manifestPath);
    std::vector<LevelIssue> issues;
    for (std::size_t e = 0; e < campaign.episodes.size(); ++e)
    {
        for (const std::string& path : campaign.episodes[e].levelPaths)
        {
            try
            {
                campaign.levels.push_back({path, e, loadLevel(path, catalog)});
            }
            catch (const LevelLoadError& error)
            {
                issues.insert(issues.end(), error.issues().begin(), error.issues().end());
            }
        }
    }
    if (!issues.empty())
        throw LevelLoadError(std::move(issues));
    return campaign;
}

} // namespace abalike
