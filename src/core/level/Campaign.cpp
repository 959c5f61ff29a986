#include <abalike/level/Campaign.hpp>

#include "design/ParallelFor.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>

namespace abalike
{

std::vector<std::string> Campaign::levelIds() const
{
    std::vector<std::string> ids;
    ids.reserve(levels.size());
    for (const CampaignLevel& entry : levels)
        ids.push_back(entry.key);
    return ids;
}

std::optional<std::size_t> Campaign::indexOf(const std::string& levelKey) const
{
    for (std::size_t i = 0; i < levels.size(); ++i)
        if (levels[i].key == levelKey)
            return i;
    return std::nullopt;
}

std::optional<std::size_t> Campaign::indexOfNumber(const std::string& levelArgument) const
{
    for (std::size_t i = 0; i < levels.size(); ++i)
        if (levels[i].levelArgument() == levelArgument)
            return i;
    return std::nullopt;
}

std::vector<std::string> Campaign::levelArguments() const
{
    std::vector<std::string> out;
    out.reserve(levels.size());
    for (const CampaignLevel& entry : levels)
        out.push_back(entry.levelArgument());
    return out;
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
    try
    {
        campaign.numberings[""] = loadLevelNumbering(manifestPath);
    }
    catch (const LevelLoadError& error)
    {
        issues.insert(issues.end(), error.issues().begin(), error.issues().end());
    }
    // Every level is read and checked on its own (the reach check flies a fan of launches: most of a campaign's
    // load), so the levels load in parallel; what follows takes them in the manifest's order, as before.
    struct Entry
    {
        std::size_t episode;
        std::size_t index;
        std::optional<LevelDef> level;
        std::vector<LevelIssue> issues;
    };
    std::vector<Entry> entries;
    for (std::size_t e = 0; e < campaign.episodes.size(); ++e)
        for (std::size_t l = 0; l < campaign.episodes[e].levelPaths.size(); ++l)
            entries.push_back({e, l, std::nullopt, {}});
    parallelFor(
        entries.size(), workerCount(0),
        [&](std::size_t i)
        {
            Entry& entry = entries[i];
            try
            {
                entry.level = loadLevel(campaign.episodes[entry.episode].levelPaths[entry.index], catalog);
            }
            catch (const LevelLoadError& error)
            {
                entry.issues = error.issues();
            }
        },
        [](std::size_t) {});

    std::map<std::string, std::string> idAt; // level id -> manifest pointer of the level that has it
    for (Entry& entry : entries)
    {
        const CampaignEpisode& episode = campaign.episodes[entry.episode];
        const LevelIssue& place = episode.levelPlaces[entry.index];
        const auto atEntry = [&](const std::string& message)
        {
            LevelIssue issue = place;
            issue.message = message;
            issues.push_back(std::move(issue));
        };
        if (!entry.level)
        {
            issues.insert(issues.end(), entry.issues.begin(), entry.issues.end());
            continue;
        }
        LevelDef& level = *entry.level;
        // "episode" is optional in a level file: one without it belongs to the episode that lists it.
        if (level.episode.empty())
            level.episode = episode.id;
        if (level.episode != episode.id && !level.sandbox) // a sandbox scene is reported as one above
            atEntry("the level says \"episode\": \"" + level.episode + "\" but is listed in episode \"" + episode.id +
                    "\" (expected them to agree)");
        const auto [first, fresh] = idAt.emplace(level.id, place.pointer);
        if (!fresh)
            atEntry("id \"" + level.id + "\" is already used by the level at " + first->second +
                    " (expected every id once: progress is saved by id)");
        const std::string key = level.id;
        const std::string number = episode.id + "-" + std::to_string(entry.index + 1);
        campaign.levels.push_back({episode.levelPaths[entry.index], entry.episode, std::move(level), key, "", number});
    }
    if (!issues.empty())
        throw LevelLoadError(std::move(issues));
    return campaign;
}

void appendLevelPack(Campaign& campaign, const std::string& packFolder, const Catalog& catalog)
{
    const std::filesystem::path folder = std::filesystem::path(packFolder);
    std::string name = folder.filename().string();
    if (name.empty() || name == ".")
        name = std::filesystem::absolute(folder).lexically_normal().filename().string();
    if (name.empty())
        name = std::filesystem::absolute(folder).parent_path().filename().string();
    const std::filesystem::path manifest = folder / "campaign.json";
    std::error_code ec;
    if (!std::filesystem::is_regular_file(manifest, ec))
        throw LevelLoadError(
            {{manifest.string(), 0, 0, "",
              "a level pack is a folder with a campaign.json (expected " + manifest.string() + " to exist)"}});
    for (const CampaignLevel& existing : campaign.levels)
        if (existing.pack == name)
            throw LevelLoadError({{manifest.string(), 0, 0, "",
                                   "a level pack named \"" + name +
                                       "\" is already loaded (expected one per name: "
                                       "progress is saved under it)"}});
    Campaign pack = loadCampaignLevels(manifest.string(), catalog);
    const std::size_t firstEpisode = campaign.episodes.size();
    for (CampaignEpisode& episode : pack.episodes)
    {
        episode.title = name + ": " + (episode.title.empty() ? episode.id : episode.title);
        campaign.episodes.push_back(std::move(episode));
    }
    campaign.numberings[name] = pack.numberings[""];
    for (CampaignLevel& level : pack.levels)
    {
        level.episode += firstEpisode;
        level.pack = name;
        level.key = name + "/" + level.level.id;
        campaign.levels.push_back(std::move(level));
    }
}

std::vector<std::string> installedLevelPacks(const std::string& packsFolder)
{
    std::vector<std::string> packs;
    std::error_code ec;
    if (!std::filesystem::is_directory(packsFolder, ec))
        return packs;
    for (const auto& entry : std::filesystem::directory_iterator(packsFolder, ec))
        if (entry.is_directory(ec) && std::filesystem::is_regular_file(entry.path() / "campaign.json", ec))
            packs.push_back(entry.path().string());
    std::sort(packs.begin(), packs.end());
    return packs;
}

} // namespace abalike
