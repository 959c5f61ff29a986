#include "level/JsonLocator.hpp"
#include "level/JsonText.hpp"
#include "level/LevelReader.hpp"
#include <abalike/level/LevelLimits.hpp>

#include <abalike/level/LevelIO.hpp>

#include <filesystem>
#include <map>

namespace abalike
{

namespace
{
/// True if the file is a level that says "sandbox": true. Anything unreadable is left to the level loader.
bool isSandboxScene(const std::string& path)
{
    try
    {
        const nlohmann::json root = parseJsonText(readJsonFile(path, kLevelText), path, kLevelText);
        const auto it = root.is_object() ? root.find("sandbox") : root.end();
        return it != root.end() && it->is_boolean() && it->get<bool>();
    }
    catch (const LevelLoadError&)
    {
        return false;
    }
}
} // namespace

bool isCampaignManifest(const std::string& path)
{
    try
    {
        const nlohmann::json root = parseJsonText(readJsonFile(path, kManifestText), path, kManifestText);
        return root.is_object() && root.contains("episodes");
    }
    catch (const LevelLoadError&)
    {
        return false;
    }
}

std::vector<CampaignEpisode> loadCampaignEpisodes(const std::string& manifestPath, bool keepGoing)
{
    const std::string text = readJsonFile(manifestPath, kManifestText);
    const nlohmann::json root = parseJsonText(text, manifestPath, kManifestText);
    const JsonLocator locator(text);
    LevelReader r(manifestPath, locator);
    r.duplicateKeys();
    r.safeText(root);
    std::vector<CampaignEpisode> out;
    std::map<std::string, std::string> listedAt; // each level file once: canonical path -> pointer of its entry
    const auto folder = std::filesystem::path(manifestPath).parent_path();
    if (r.object(root, "", {"$schema", "format", "title", "episodes", "renumbered"}))
    {
        const auto episodes = root.find("episodes");
        if (episodes == root.end())
            r.error("", "missing required key \"episodes\" (expected an array of episodes)");
        else if (r.array(*episodes, "/episodes", 1, 100, "episodes"))
        {
            for (std::size_t e = 0; e < episodes->size(); ++e)
            {
                const nlohmann::json& episode = (*episodes)[e];
                const std::string p = "/episodes/" + std::to_string(e);
                if (!r.object(episode, p, {"id", "title", "levels"}))
                    continue;
                CampaignEpisode item;
                item.id = r.string(episode, p, "id", "", true);
                item.title = r.string(episode, p, "title", "", false);
                const auto levels = episode.find("levels");
                if (levels == episode.end())
                {
                    r.error(p, "missing required key \"levels\" (expected an array of level file names)");
                    continue;
                }
                if (!r.array(*levels, p + "/levels", 1, 1000, "level file names"))
                    continue;
                for (std::size_t l = 0; l < levels->size(); ++l)
                {
                    const std::string at = p + "/levels/" + std::to_string(l);
                    if ((*levels)[l].is_string())
                    {
                        const std::string name = (*levels)[l].get<std::string>();
                        const std::filesystem::path path = folder / name;
                        std::error_code ec;
                        if (!std::filesystem::is_regular_file(path, ec))
                        {
                            r.error(at, "no level file \"" + name + "\" next to the manifest (expected " +
                                            path.generic_string() + " to exist)");
                            continue;
                        }
                        const auto [first, fresh] =
                            listedAt.emplace(std::filesystem::weakly_canonical(path, ec).string(), at);
                        if (!fresh)
                        {
                            r.error(at, "\"" + name + "\" is already listed at " + first->second +
                                            " (expected each level once)");
                            continue;
                        }
                        item.levelPaths.push_back(path.string());
                        const auto [line, column] = locator.locate(at);
                        item.levelPlaces.push_back({manifestPath, line, column, at, ""});
                        if (isSandboxScene(item.levelPaths.back()))
                        {
                            std::string message = "\"";
                            message += (*levels)[l].get<std::string>();
                            message += "\" is a sandbox scene (expected a level to play: a campaign lists no "
                                       "\"sandbox\": true scene)";
                            r.error(at, message);
                        }
                    }
                    else
                        r.error(at, "expected a level file name, got " + describeJsonType((*levels)[l]));
                }
                out.push_back(std::move(item));
            }
        }
    }
    if (!r.ok() && !keepGoing)
        throw LevelLoadError(r.take());
    return out;
}

std::vector<std::string> loadCampaign(const std::string& manifestPath)
{
    std::vector<std::string> paths;
    for (const CampaignEpisode& episode : loadCampaignEpisodes(manifestPath))
        paths.insert(paths.end(), episode.levelPaths.begin(), episode.levelPaths.end());
    return paths;
}

} // namespace abalike
