#pragma once

#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace abalike
{

/// The best a player has done on one level.
struct LevelRecord
{
    int bestScore = 0;
    int stars = 0; ///< 0 to 3: the most stars ever earned, possibly in another play than bestScore

    bool operator==(const LevelRecord&) const = default;
};

/// The best the player has done in the endless mode (runs of generated levels, EndlessRun).
struct EndlessRecord
{
    int bestScore = 0;  ///< the highest score of one run
    int longestRun = 0; ///< the most levels won in one run
    int runs = 0;       ///< runs ended (the first level of a session rotates through the shipped set by it)

    /// A run has now won `levelsWon` levels for `score` points (offered after every win, so that a run the player
    /// leaves still counts): keeps the bests. Returns true when one improved.
    bool offer(int levelsWon, int score);

    bool operator==(const EndlessRecord&) const = default;
};

/// What a player has achieved: the best result per level and the levels they may play, keyed by level id.
struct Progress
{
    std::map<std::string, LevelRecord> levels;
    std::set<std::string> unlocked;
    EndlessRecord endless;
    /// Which numbering of its levels' ids (LevelNumbering) the keys of each campaign part follow: "" for the bundled
    /// campaign, a level pack's name for its "PACK/ID" keys. A part missing here is read as numbering 1.
    std::map<std::string, int> numbering;

    /// Keeps the better of the stored and the new score and stars; returns true when something improved.
    bool record(const std::string& levelId, int score, int stars);
    /// Returns true when the level was not unlocked before.
    bool unlock(const std::string& levelId);
    bool isUnlocked(const std::string& levelId) const { return unlocked.contains(levelId); }

    bool operator==(const Progress&) const = default;
};

/// Opens the first level of the campaign, every level won with at least one star (however it was reached) and
/// every level that follows one.
/// Returns true when a level was newly unlocked.
bool unlockCampaign(Progress& progress, const std::vector<std::string>& levelIds);

/// Parses the text of progress.json, of this version (format 3) or an earlier one (format 2, before the level
/// numberings: read as numbering 1 everywhere; format 1, before the endless mode: the endless record starts empty).
/// Throws SaveFormatError saying what is wrong and where.
Progress parseProgress(std::string_view text);

/// The text of progress.json, always of this version (stable key order, so saving unchanged progress writes the same
/// bytes).
std::string progressToJson(const Progress& progress);

} // namespace abalike
