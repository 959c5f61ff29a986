#include "endless/EndlessGame.hpp"

#include <abalike/level/LevelIO.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/world/Catalog.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace abalike::app
{

namespace
{

/// "101-0.3" -> seed 101, 3 tenths; nothing for another name.
std::optional<std::pair<std::uint64_t, int>> parseEndlessName(const std::string& stem)
{
    const std::size_t dash = stem.find('-');
    if (dash == std::string::npos || dash == 0 || dash > 18 || stem.find_first_not_of("0123456789") != dash)
        return std::nullopt;
    const std::string share = stem.substr(dash + 1);
    char* end = nullptr;
    const double value = std::strtod(share.c_str(), &end);
    if (share.empty() || end != share.c_str() + share.size() || !(value >= 0.1 && value <= 0.9))
        return std::nullopt;
    const int tenths = static_cast<int>(std::lround(value * 10.0));
    if (std::abs(value * 10.0 - tenths) > 1e-9)
        return std::nullopt;
    return std::pair{std::stoull(stem.substr(0, dash)), tenths};
}

} // namespace

std::string EndlessLevel::generatedName() const
{
    return std::to_string(seed) + ":" + shortestNumber(lossShareTenths / 10.0);
}

std::vector<EndlessLevel> loadShippedEndlessLevels(const std::filesystem::path& folder)
{
    std::vector<EndlessLevel> levels;
    for (const std::string& file : levelFilesIn(folder.string()))
    {
        const auto name = parseEndlessName(std::filesystem::path(file).stem().string());
        if (!name)
            throw LevelLoadError({LevelIssue{file, 0, 0, "",
                                             "a shipped endless level is named SEED-L.json (e.g. 101-0.3.json), as "
                                             "`abalike generate --seed SEED --loss-share L` makes it"}});
        levels.push_back({loadLevel(file, Catalog::builtin()), name->first, name->second, true});
    }
    return levels;
}

EndlessGame::EndlessGame(const std::filesystem::path& levels, std::filesystem::path cache, std::uint64_t firstSeed,
                         int runsEnded, bool scripted)
    : m_cache(std::move(cache)), m_runsEnded(std::max(runsEnded, 0)), m_scripted(scripted)
{
    try
    {
        // None shipped is no problem: the first level is then waited for.
        m_shipped = loadShippedEndlessLevels(levels / "endless");
    }
    catch (const LevelLoadError& error)
    {
        m_problem = error.what();
    }
    m_played.assign(m_shipped.size(), false);
    std::vector<GeneratorPart> parts;
    try
    {
        parts = loadGeneratorParts((levels / "parts").string(), Catalog::builtin());
    }
    catch (const LevelLoadError& error)
    {
        m_problem = error.what();
    }
    if (parts.empty() && m_problem.empty())
        m_problem = "no castle parts in " + (levels / "parts").string();
    const std::filesystem::path schema = levels / "schema" / "level.schema.json";
    auto generate = [parts = std::move(parts), cache = m_cache, schema](const GeneratorOptions& options)
    {
        GeneratedLevel made = generateLevel(parts, options, Catalog::builtin());
        if (made.ok)
        {
            // Kept where `play --generated SEED:L` looks first: the level shown as "Castle 4711" replays as it was.
            std::error_code ignored;
            std::filesystem::create_directories(cache, ignored);
            try
            {
                saveLevel(made.level,
                          cache / (std::to_string(options.seed) + "-" + shortestNumber(options.lossShare) + ".json"),
                          schema);
            }
            catch (const std::exception&)
            {
                // A cache that cannot be written costs only the replay's wait; the level is played all the same.
            }
        }
        return made;
    };
    m_queue = std::make_unique<GeneratedLevelQueue>(std::move(generate), GeneratorOptions{}, firstSeed);
}

EndlessGame::~EndlessGame() = default;

std::optional<EndlessLevel> EndlessGame::nextLevel()
{
    const int tenths = m_run.lossShareTenths();
    std::optional<EndlessLevel> next = m_scripted ? shippedLevel(tenths) : std::nullopt;
    if (!next && m_scripted && m_problem.empty())
    {
        m_queue->want({tenths});
        if (std::optional<GeneratedLevel> made = m_queue->takeWaiting(tenths, std::chrono::hours(1)))
            next = EndlessLevel{std::move(made->level), made->seed, tenths, false};
    }
    else if (!next)
    {
        if (std::optional<GeneratedLevel> made = m_queue->take(tenths))
            next = EndlessLevel{std::move(made->level), made->seed, tenths, false};
        else
            next = shippedLevel(tenths);
    }
    m_playing = next.has_value();
    if (next)
        m_queue->want({m_run.tenthsAfterWin(), m_run.tenthsAfterLoss()});
    else
        m_queue->want({tenths, m_run.tenthsAfterWin(), m_run.tenthsAfterLoss()});
    return next;
}

std::optional<EndlessLevel> EndlessGame::shippedLevel(int tenths)
{
    // The unplayed shipped levels nearest the share; among them the player's runs so far pick one, so that a new
    // session does not always open on the same castle.
    std::vector<std::size_t> nearest;
    int best = 100;
    for (std::size_t i = 0; i < m_shipped.size(); ++i)
    {
        if (m_played[i])
            continue;
        const int distance = std::abs(m_shipped[i].lossShareTenths - tenths);
        if (distance < best)
            nearest.clear();
        if (distance <= best)
        {
            best = distance;
            nearest.push_back(i);
        }
    }
    if (nearest.empty())
        return std::nullopt;
    const std::size_t pick = nearest[static_cast<std::size_t>(m_runsEnded) % nearest.size()];
    m_played[pick] = true;
    return m_shipped[pick];
}

GeneratedLevelQueue::Status EndlessGame::generation() const
{
    return m_queue->status();
}

} // namespace abalike::app
