#include "shell/PlayerProgress.hpp"

#include "endless/EndlessGame.hpp"
#include "shell/AppOptions.hpp"
#include "shell/DataPaths.hpp"
#include "shell/Notices.hpp"
#include "shell/PlayerSettings.hpp"
#include "shell/Trace.hpp"

#include <abalike/save/DataDirectory.hpp>
#include <abalike/save/ProgressNumbering.hpp>
#include <abalike/save/SaveStore.hpp>
#include <chrono>
#include <filesystem>

namespace abalike::app
{

PlayerProgress::PlayerProgress(Campaign campaign, const AppOptions& options, SaveStore* store,
                               const PlayerSettings& settings, Trace& trace, Notices& notices)
    : m_campaign(std::move(campaign)), m_options(options), m_store(store), m_settings(settings), m_trace(trace),
      m_notices(notices)
{
    if (m_store == nullptr)
        return;
    m_progress = m_store->progress();
    const bool renumbered = renumberProgress(m_progress, m_campaign);
    if ((unlockCampaign(m_progress, m_campaign.levelIds()) || renumbered) && !m_options.scripted())
        m_store->saveProgress(m_progress);
}

PlayerProgress::~PlayerProgress() = default;

bool PlayerProgress::isUnlocked(const std::string& levelId) const
{
    return m_settings.current().openAllLevels || m_progress.isUnlocked(levelId);
}

void PlayerProgress::recordResult(const std::string& levelId, int score, int stars)
{
    const bool improved = m_progress.record(levelId, score, stars);
    const bool unlocked = unlockCampaign(m_progress, m_campaign.levelIds());
    m_trace.write("result", {{"level", levelId}, {"score", score}, {"stars", stars}});
    if (improved || unlocked)
        save();
    if (m_store != nullptr)
        m_notices.takeMessagesOf(*m_store);
}

EndlessGame& PlayerProgress::endless()
{
    if (!m_endless)
    {
        // Seeds from the clock, so that every session generates castles of its own; --seed makes a run repeatable.
        const auto clock = static_cast<std::uint64_t>(std::chrono::system_clock::now().time_since_epoch().count());
        const std::uint64_t seed = m_options.endlessSeed.value_or(1000 + clock % 90000);
        m_endless = std::make_unique<EndlessGame>(std::filesystem::path(levelsDirectory()),
                                                  defaultCacheDirectory() / "generated", seed, m_progress.endless.runs,
                                                  m_options.scripted());
    }
    return *m_endless;
}

void PlayerProgress::recordEndless(int levelsWon, int score, bool ended)
{
    bool changed = m_progress.endless.offer(levelsWon, score);
    if (ended)
    {
        ++m_progress.endless.runs;
        changed = true;
    }
    m_trace.write("endless-record", {{"levels_won", levelsWon},
                                     {"score", score},
                                     {"ended", ended},
                                     {"best_score", m_progress.endless.bestScore},
                                     {"longest_run", m_progress.endless.longestRun}});
    if (changed)
        save();
    if (m_store != nullptr)
        m_notices.takeMessagesOf(*m_store);
}

void PlayerProgress::save()
{
    if (!m_options.scripted() && m_store != nullptr)
        m_store->saveProgress(m_progress);
}

} // namespace abalike::app
