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

std::string StagedDifficulty::describe(const std::string& what, const PlayerDifficulty& sofar) const
{
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    std::ostringstream line;
    line << m_level.id << ": " << what << " (" << sofar.runs << " of " << m_runs << " model player runs, " << std::fixed
         << std::setprecision(1) << seconds << " s): " << sofar.wins << " won (" << percent(sofar.winShare)
         << " %, 90 % interval " << percent(sofar.low90) << "-" << percent(sofar.high90) << " %)";
    if (!sofar.winScores.empty())
    {
        const auto stars = recommendedStars(sofar, 0);
        line << ", stars about " << stars[0] << " / " << stars[1] << " / " << stars[2];
    }
    return line.str();
}

void StagedDifficulty::estimate(std::ostream& out)
{
    const std::size_t runs = std::min(m_runs, kFirstEstimateRuns);
    if (runs == 0)
        return;
    m_first = play(firstRuns(runs), "model player, first estimate ");
    std::string line = describe("first estimate", *m_first);
    if (m_runs > runs)
        line += "; refining with the solver and " + std::to_string(m_runs - runs) + " more runs";
    out << line << std::endl;
}

PlayerDifficulty StagedDifficulty::finish(std::ostream& out)
{
    if (!m_first)
        return play(firstRuns(m_runs), "model player ");
    PlayerDifficulty sofar = *m_first;
    while (sofar.runs < m_runs)
    {
        const std::size_t upTo = std::min(m_runs, sofar.runs + kRefineRuns);
        sofar = joinDifficulty(sofar, play(runsAfter(firstRuns(0), sofar, upTo), "model player "));
        if (sofar.runs < m_runs)
            out << describe("refined", sofar) << std::endl;
    }
    return sofar;
}

ModelPlayerOptions StagedDifficulty::firstRuns(std::size_t runs) const
{
    ModelPlayerOptions options;
    options.runs = runs;
    options.threads = m_threads;
    return options;
}

} // namespace abalike::app
