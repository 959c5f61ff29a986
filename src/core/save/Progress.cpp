#include "save/SaveJson.hpp"

#include <abalike/save/Progress.hpp>
#include <abalike/save/SaveError.hpp>
#include <algorithm>
#include <limits>

namespace abalike
{

namespace
{

/// 2: the endless record; 3: the numbering of the level ids (LevelNumbering). Earlier files are read as they are,
/// with an empty endless record (1) and every level id of numbering 1 (1 and 2).
constexpr int kProgressFormat = 3;
constexpr int kOldestProgressFormat = 1;
constexpr int kMaxStars = 3;
/// A campaign renumbered once a day for three years stays below it.
constexpr int kMaxNumbering = 1000;
/// Level ids are short names like "2-3"; a longer one is not from a level file.
constexpr std::size_t kMaxIdLength = 256;

/// A key as a JSON pointer token (RFC 6901), so a message points at the right member.
std::string pointerToken(const std::string& key)
{
    std::string out;
    for (const char c : key)
        out += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
    return out;
}

bool validId(const std::string& id)
{
    return !id.empty() && id.size() <= kMaxIdLength;
}

void checkId(const std::string& id, const std::string& pointer)
{
    if (!validId(id))
        throw SaveFormatError(pointer + ": a level id has 1 to " + std::to_string(kMaxIdLength) + " characters");
}

} // namespace

bool Progress::record(const std::string& levelId, int score, int stars)
{
    const bool isNew = !levels.contains(levelId);
    LevelRecord& best = levels[levelId];
    const LevelRecord before = best;
    best.bestScore = std::max(best.bestScore, std::max(score, 0));
    best.stars = std::max(best.stars, std::clamp(stars, 0, kMaxStars));
    return isNew || !(best == before);
}

bool EndlessRecord::offer(int levelsWon, int score)
{
    const EndlessRecord before = *this;
    bestScore = std::max(bestScore, std::max(score, 0));
    longestRun = std::max(longestRun, std::max(levelsWon, 0));
    return !(*this == before);
}

bool Progress::unlock(const std::string& levelId)
{
    return unlocked.insert(levelId).second;
}

bool unlockCampaign(Progress& progress, const std::vector<std::string>& levelIds)
{
    bool changed = false;
    // Each chain unlocks on its own: the bundled campaign (plain ids) and every level pack ("PACK/ID").
    const auto packOf = [](const std::string& key)
    {
        const auto slash = key.find('/');
        return slash == std::string::npos ? std::string() : key.substr(0, slash);
    };
    for (std::size_t i = 0; i < levelIds.size(); ++i)
    {
        const bool first = i == 0 || packOf(levelIds[i]) != packOf(levelIds[i - 1]);
        const auto won = [&](const std::string& key)
        {
            const auto record = progress.levels.find(key);
            return record != progress.levels.end() && record->second.stars >= 1;
        };
        // A level won however it was reached (`play --level`, a test play) is open, with its stars on its tile.
        if (first || won(levelIds[i]) || won(levelIds[i - 1]))
            changed = progress.unlock(levelIds[i]) || changed;
    }
    return changed;
}

Progress parseProgress(std::string_view text)
{
    const nlohmann::json root = parseSaveJson(text, kProgressFormat, kOldestProgressFormat);
    Progress progress;
    if (const auto levels = root.find("levels"); levels != root.end())
    {
        if (!levels->is_object())
            throw SaveFormatError("/levels: expected an object of level id -> {\"best_score\", \"stars\"}");
        for (const auto& [id, entry] : levels->items())
        {
            const std::string pointer = "/levels/" + pointerToken(id);
            checkId(id, pointer);
            if (!entry.is_object())
                throw SaveFormatError(pointer + ": expected an object with \"best_score\" and \"stars\"");
            LevelRecord record;
            if (const auto score = entry.find("best_score"); score != entry.end())
                record.bestScore = readInt(*score, pointer + "/best_score", 0, std::numeric_limits<int>::max());
            if (const auto stars = entry.find("stars"); stars != entry.end())
                record.stars = readInt(*stars, pointer + "/stars", 0, kMaxStars);
            progress.levels[id] = record;
        }
    }
    if (const auto unlocked = root.find("unlocked"); unlocked != root.end())
    {
        if (!unlocked->is_array())
            throw SaveFormatError("/unlocked: expected an array of level ids");
        for (std::size_t i = 0; i < unlocked->size(); ++i)
        {
            const std::string pointer = "/unlocked/" + std::to_string(i);
            const std::string& id = readString((*unlocked)[i], pointer);
            checkId(id, pointer);
            progress.unlocked.insert(id);
        }
    }
    if (const auto endless = root.find("endless"); endless != root.end())
    {
        if (!endless->is_object())
            throw SaveFormatError("/endless: expected an object with \"best_score\", \"longest_run\" and \"runs\"");
        const auto member = [&endless](const char* key, int& into)
        {
            if (const auto value = endless->find(key); value != endless->end())
                into = readInt(*value, std::string("/endless/") + key, 0, std::numeric_limits<int>::max());
        };
        member("best_score", progress.endless.bestScore);
        member("longest_run", progress.endless.longestRun);
        member("runs", progress.endless.runs);
    }
    if (const auto numbering = root.find("numbering"); numbering != root.end())
    {
        if (!numbering->is_object())
            throw SaveFormatError("/numbering: expected an object of campaign part (\"\" or a level pack's name) -> "
                                  "numbering of its level ids");
        for (const auto& [part, value] : numbering->items())
            progress.numbering[part] = readInt(value, "/numbering/" + pointerToken(part), 1, kMaxNumbering);
    }
    return progress;
}

std::string progressToJson(const Progress& progress)
{
    nlohmann::ordered_json root;
    root["format"] = kProgressFormat;
    nlohmann::ordered_json levels = nlohmann::ordered_json::object();
    // Write only what parseProgress accepts: one odd entry must never make the whole file unreadable.
    for (const auto& [id, record] : progress.levels)
        if (validId(id))
            levels[id] = {{"best_score", std::max(record.bestScore, 0)},
                          {"stars", std::clamp(record.stars, 0, kMaxStars)}};
    root["levels"] = std::move(levels);
    nlohmann::ordered_json unlocked = nlohmann::ordered_json::array();
    for (const std::string& id : progress.unlocked)
        if (validId(id))
            unlocked.push_back(id);
    root["unlocked"] = std::move(unlocked);
    root["endless"] = {{"best_score", std::max(progress.endless.bestScore, 0)},
                       {"longest_run", std::max(progress.endless.longestRun, 0)},
                       {"runs", std::max(progress.endless.runs, 0)}};
    nlohmann::ordered_json numbering = nlohmann::ordered_json::object();
    for (const auto& [part, value] : progress.numbering)
        numbering[part] = std::clamp(value, 1, kMaxNumbering);
    root["numbering"] = std::move(numbering);
    return dumpSaveJson(root);
}

} // namespace abalike
