#include "design/DropAims.hpp"

#include <box2d/box2d.h>

#include <array>
#include <cmath>

namespace abalike
{

namespace
{

struct Target
{
    int pig = -1;
    double x = 0.0;
    double topY = 0.0;
};

/// Where a payload let go at (x, y) with velocity (vx, vy) comes down to height targetY, and how fast it falls
/// there; false when it starts below that height.
bool landing(double x, double y, double vx, double vy, double targetY, double g, double& landX, double& fallMps)
{
    const double drop = y - targetY;
    if (drop <= 0.0 || g <= 0.0)
        return false;
    const double tau = (vy + std::sqrt(vy * vy + 2.0 * g * drop)) / g;
    landX = x + vx * tau;
    fallMps = g * tau - vy;
    return true;
}

/// A sample of the flown path with the bird's velocity there (the path's slope over the step before it).
struct FlightSample
{
    double t = 0.0;
    double x = 0.0;
    double y = 0.0;
    double vx = 0.0;
    double vy = 0.0;
};

std::vector<FlightSample> freeFlight(const ShotRecord& shot)
{
    const std::vector<TrackPoint>& path = shot.actualPath;
    const double endS = shot.actualContact ? shot.actualContact->t : (path.empty() ? 0.0 : path.back().timeS);
    std::vector<FlightSample> samples;
    for (std::size_t i = 1; i < path.size() && path[i].timeS <= endS; ++i)
    {
        const double dt = path[i].timeS - path[i - 1].timeS;
        if (dt > 0.0)
            samples.push_back({path[i].timeS, path[i].position.x, path[i].position.y,
                               (path[i].position.x - path[i - 1].position.x) / dt,
                               (path[i].position.y - path[i - 1].position.y) / dt});
    }
    return samples;
}

} // namespace

std::vector<DropAim> dropAims(const GameSession& session, const DroppedPayload& payload)
{
    std::vector<DropAim> aims;
    if (session.shots().empty())
        return aims;
    const ShotRecord& shot = session.shots().back();
    // The catalog, not the world: by the time the solver asks, the bird may have been retired from the world.
    const BirdType* bird = session.catalog().findBird(shot.bird);
    const double birdRadius = bird != nullptr ? bird->radiusM : 0.0;
    std::vector<Target> targets;
    for (const Entity& e : session.world().entities())
    {
        if (e.kind != EntityKind::Pig || !e.alive || e.body == nullptr)
            continue;
        const b2Vec2 at = e.body->GetPosition();
        targets.push_back({e.defIndex, at.x, at.y + 0.5 * e.widthM + payload.radiusM});
    }
    const std::vector<FlightSample> samples = freeFlight(shot);
    const double g = session.level().environment.gravity;
    // The payload leaves below the bird, payload.speedMps faster downwards.
    for (const Target& target : targets)
    {
        double previousMiss = 0.0;
        double previousS = -1.0;
        for (const FlightSample& s : samples)
        {
            double landX = 0.0;
            double fall = 0.0;
            if (!landing(s.x, s.y - birdRadius - payload.radiusM, s.vx, s.vy - payload.speedMps, target.topY, g, landX,
                         fall))
            {
                previousS = -1.0;
                continue;
            }
            const double miss = landX - target.x;
            if (previousS >= 0.0 && (previousMiss < 0.0) != (miss < 0.0))
            {
                // Between two samples the landing point passed over the pig: interpolate the moment.
                const double share = previousMiss / (previousMiss - miss);
                aims.push_back({target.pig, previousS + share * (s.t - previousS), fall});
            }
            previousMiss = miss;
            previousS = s.t;
        }
    }
    return aims;
}

} // namespace abalike
