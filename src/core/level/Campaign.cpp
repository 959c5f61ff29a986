#include <abalike/level/Campaign.hpp>

#include <map>

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
    std::vector<LevelIssue> issues;
    try
    {
        campaign.episodes = loadCampaignEpisodes(manifestPath);
    }
    catch (const LevelLoadError& error)
    {
        // The manifest's own problems do not hide the levels' ones: report what the readable entries hold too.
        issues = error.issues();
        try
        {
            campaign.episodes = loadCampaignEpisodes(manifestPath, true);
        }
        catch (const LevelLoadError&)
        {
            throw LevelLoadError(std::move(issues));
        }
    }
    std::map<std::string, std::string> idAt; // level id -> manifest pointer of the level that has it
    for (std::size_t e = 0; e < campaign.episodes.size(); ++e)
    {
        const CampaignEpisode& episode = campaign.episodes[e];
        for (std::size_t l = 0; l < episode.levelPaths.size(); ++l)
        {
            const LevelIssue& place = episode.levelPlaces[l];
            const auto atEntry = [&](const std::string& message)
            {
                LevelIssue issue = place;
                issue.message = message;
                issues.push_back(std::move(issue));
            };
            try
            {
                LevelDef level = loadLevel(episode.levelPaths[l], catalog);
                if (level.episode != episode.id && !level.sandbox) // a sandbox scene is reported as one above
                    atEntry("the level says \"episode\": \"" + level.episode + "\" but is listed in episode \"" +
                            episode.id + "\" (expected them to agree)");
                const auto [first, fresh] = idAt.emplace(level.id, place.pointer);
                if (!fresh)
                    atEntry("id \"" + level.id + "\" is already used by the level at " + first->second +
                            " (expected every id once: progress is saved by id)");
                campaign.levels.push_back({episode.levelPaths[l], e, std::move(level)});
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
