#include "cli/StagedDifficulty.hpp"

#include "cli/ProgressBar.hpp"

#include <abalike/design/StarThresholds.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace abalike::app
{

namespace
{

std::string percent(double share)
{
    return std::to_string(static_cast<int>(std::lround(100.0 * share)));
}

} // namespace

StagedDifficulty::StagedDifficulty(const LevelDef& level, std::size_t runs, int threads)
    : m_level(level), m_runs(runs), m_threads(threads), m_start(std::chrono::steady_clock::now())
{
}

PlayerDifficulty StagedDifficulty::play(const ModelPlayerOptions& options, const std::string& label)
{
    ProgressBar bar(label + m_level.id);
    ModelPlayerOptions withBar = options;
    withBar.progress = [&bar](std::size_t done, std::size_t total)
    {
        bar.update(done, total);
    };
    PlayerDifficulty result = measurePlayerDifficulty(m_level, Catalog::builtin(), withBar);
    bar.finish();
    return result;
}

void StagedDifficulty::estimate(std::ostream& out)
{
    const std::size_t runs = std::min(m_runs, kFirstEstimateRuns);
    if (runs == 0)
        return;
    m_first = play(firstRuns(runs), "model player, first estimate ");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    const PlayerDifficulty& first = *m_first;
    std::ostringstream line;
    line << m_level.id << ": first estimate (" << first.runs << " of " << m_runs << " model player runs, " << std::fixed
         << std::setprecision(1) << seconds << " s): " << first.wins << " won (" << percent(first.winShare)
         << " %, 90 % interval " << percent(first.low90) << "-" << percent(first.high90) << " %)";
    if (!first.winScores.empty())
    {
        const auto stars = recommendedStars(first, 0);
        line << ", stars about " << stars[0] << " / " << stars[1] << " / " << stars[2];
    }
    if (m_runs > runs)
        line << "; refining with the solver and " << m_runs - runs << " more runs";
    out << line.str() << std::endl;
}

PlayerDifficulty StagedDifficulty::finish()
{
    if (!m_first)
        return play(firstRuns(m_runs), "model player ");
    if (m_runs <= m_first->runs)
        return *m_first;
    return joinDifficulty(*m_first, play(runsAfter(firstRuns(m_first->runs), *m_first, m_runs), "model player "));
}

ModelPlayerOptions StagedDifficulty::firstRuns(std::size_t runs) const
{
    ModelPlayerOptions options;
    options.runs = runs;
    options.threads = m_threads;
    return options;
}

} // namespace abalike::app
