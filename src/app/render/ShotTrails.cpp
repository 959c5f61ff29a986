#include "render/ShotTrails.hpp"

#include <algorithm>
#include <iterator>

namespace abalike::app
{

namespace
{
/// Distinct colours for successive shots (colour-blind friendly, Okabe-Ito).
const sf::Color kShotColours[] = {{230, 159, 0}, {86, 180, 233}, {0, 158, 115}, {240, 228, 66}, {204, 121, 167}};
} // namespace

std::vector<PathSample> samplesOf(const std::vector<TrackPoint>& path)
{
    std::vector<PathSample> samples;
    samples.reserve(path.size());
    for (std::size_t i = 0; i < path.size(); ++i)
    {
        // Central differences inside, one-sided at the ends; a zero-length interval (a contact point recorded at
        // a step's own time) borrows its neighbour's.
        const std::size_t lo = i == 0 ? 0 : i - 1;
        const std::size_t hi = std::min(i + 1, path.size() - 1);
        const double dt = path[hi].timeS - path[lo].timeS;
        PathSample s{path[i].timeS, path[i].position.x, path[i].position.y, 0.0, 0.0};
        if (dt > 1e-9)
        {
            s.vx = (path[hi].position.x - path[lo].position.x) / dt;
            s.vy = (path[hi].position.y - path[lo].position.y) / dt;
        }
        else if (!samples.empty())
        {
            s.vx = samples.back().vx;
            s.vy = samples.back().vy;
        }
        samples.push_back(s);
    }
    return samples;
}

void ShotTrails::onLevelStart(const GameSession& session)
{
    if (session.level().id != m_levelId)
        clear();
    m_levelId = session.level().id;
    m_seenShots = 0;
    m_backIsLive = false;
}

void ShotTrails::clear()
{
    m_paths.clear();
    m_backIsLive = false;
    m_shotNumber = 0;
}

void ShotTrails::update(const GameSession& session)
{
    const std::vector<ShotRecord>& shots = session.shots();
    if (shots.size() < m_seenShots)
    {
        m_seenShots = 0; // the session restarted under us
        m_backIsLive = false;
    }
    while (m_seenShots < shots.size())
    {
        MeasuredPath path;
        path.name = "shot " + std::to_string(++m_shotNumber);
        path.colour = kShotColours[static_cast<std::size_t>(m_shotNumber - 1) % std::size(kShotColours)];
        m_paths.push_back(std::move(path));
        if (m_paths.size() > kMaxPaths)
            m_paths.pop_front();
        ++m_seenShots;
        m_backIsLive = true;
    }
    if (m_backIsLive && !shots.empty() && shots.back().actualPath.size() != m_paths.back().samples.size())
        m_paths.back().samples = samplesOf(shots.back().actualPath);
}

} // namespace abalike::app
