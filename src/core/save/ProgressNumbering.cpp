#include <abalike/save/ProgressNumbering.hpp>

#include <algorithm>

namespace abalike
{

namespace
{

/// The key a level of `part` has after renumbering, or the key itself when it belongs to another part.
std::string keyNow(const std::string& key, const std::string& part, const LevelNumbering& numbering, int since)
{
    if (part.empty())
        return key.find('/') == std::string::npos ? numbering.idNow(key, since) : key;
    const std::string prefix = part + "/";
    if (!key.starts_with(prefix))
        return key;
    return prefix + numbering.idNow(key.substr(prefix.size()), since);
}

} // namespace

bool renumberProgress(Progress& progress, const std::string& part, const LevelNumbering& numbering)
{
    const auto saved = progress.numbering.find(part);
    const int since = saved == progress.numbering.end() ? 1 : saved->second;
    const int now = numbering.current();
    // Saved by a later campaign than this one (an older game opening newer progress): its keys are not ours to
    // rename, and the numbering stays, so the later campaign does not rename them again.
    if (since >= now)
        return false;
    progress.numbering[part] = now;
    // Renamed all at once (a reorder is a permutation: "1-4" -> "1-6" while "1-6" -> "1-5").
    std::map<std::string, LevelRecord> levels;
    for (const auto& [key, record] : progress.levels)
    {
        LevelRecord& into = levels[keyNow(key, part, numbering, since)];
        into.bestScore = std::max(into.bestScore, record.bestScore);
        into.stars = std::max(into.stars, record.stars);
    }
    std::set<std::string> unlocked;
    for (const std::string& key : progress.unlocked)
        unlocked.insert(keyNow(key, part, numbering, since));
    progress.levels = std::move(levels);
    progress.unlocked = std::move(unlocked);
    return true;
}

bool renumberProgress(Progress& progress, const Campaign& campaign)
{
    bool changed = false;
    for (const auto& [part, numbering] : campaign.numberings)
        changed = renumberProgress(progress, part, numbering) || changed;
    return changed;
}

} // namespace abalike
