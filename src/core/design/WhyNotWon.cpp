#include <abalike/design/WhyNotWon.hpp>
#include <abalike/flight/Prediction.hpp>
#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelCatalog.hpp>
#include <abalike/level/LevelFlight.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

namespace abalike
{

namespace
{

/// Launch angles tried, and how long a free flight is followed.
constexpr double kWhyLowestAngleDeg = -10.0;
constexpr double kWhyHighestAngleDeg = 85.0;
constexpr double kWhyAngleStepDeg = 0.5;
constexpr double kWhyFlightS = 12.0;
/// Of the launches that reach the pig, at most this many are played to see what they hit first.
constexpr std::size_t kWhyPlayed = 12;

std::string missText(double m)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f m", m);
    return text;
}

/// The closest the flight's path comes to (x, y).
double closestApproachTo(const PredictedFlight& flight, double x, double y)
{
    double best = 1e300;
    for (std::size_t i = 1; i < flight.path.size(); ++i)
    {
        const PathPoint& a = flight.path[i - 1];
        const PathPoint& b = flight.path[i];
        const double ax = a.state.position.x, ay = a.state.position.y;
        const double dx = b.state.position.x - ax;
        const double dy = b.state.position.y - ay;
        const double length2 = dx * dx + dy * dy;
        const double t = length2 > 0.0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / length2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(ax + t * dx - x, ay + t * dy - y));
    }
    return best;
}

} // namespace

std::string whyPigSurvives(const LevelDef& level, const Catalog& base, int pigIndex)
{
    if (level.birds.empty() || pigIndex < 0 || static_cast<std::size_t>(pigIndex) >= level.pigs.size())
        return {};
    const Catalog catalog = levelCatalog(level, base);
    const BirdType* bird = catalog.findBird(level.birds.front());
    const PigDef& pig = level.pigs[static_cast<std::size_t>(pigIndex)];
    const PigType* pigType = catalog.findPig(pig.type);
    if (bird == nullptr || pigType == nullptr)
        return {};
    const double speed = maxLaunchSpeed(level, *bird, catalog);
    const FlightModel model = levelFlightModel(level.environment, *bird);
    PredictionLimits limits;
    limits.maxTimeS = kWhyFlightS;
    const double reach = pigType->radiusM + bird->radiusM;
    std::vector<double> reaching;
    double nearest = 1e300;
    for (double angle = kWhyLowestAngleDeg; angle <= kWhyHighestAngleDeg + 1e-9; angle += kWhyAngleStepDeg)
    {
        const PredictedFlight free =
            predictFlight(model, {}, launchState(level.slingshot.x, level.slingshot.y, speed, angle), limits);
        const double miss = closestApproachTo(free, pig.x, pig.y);
        nearest = std::min(nearest, miss);
        if (miss <= reach)
            reaching.push_back(angle);
    }
    if (reaching.empty())
        return "out of reach (at full pull the " + bird->name + " bird's nearest path passes " +
               missText(nearest - reach) + " from it)";

    // What the launches that would reach it meet first, played in the world.
    std::map<std::pair<int, int>, std::size_t> firstHits; // (kind: 0 block, 1 pig), index -> launches
    const std::size_t stride = std::max<std::size_t>(1, reaching.size() / kWhyPlayed);
    for (std::size_t i = 0; i < reaching.size(); i += stride)
    {
        try
        {
            const auto session = simulateShots(level, {{reaching[i], speed}}, base);
            const ShotRecord& shot = session->shots().front();
            if (shot.impact)
                ++firstHits[{shot.impact->bodyKind == EntityKind::Pig ? 1 : 0, shot.impact->bodyIndex}];
        }
        catch (const LaunchError&)
        {
        }
    }
    if (firstHits.empty())
        return "the launches that reach it touch nothing first, yet it stands";
    const auto most = std::max_element(firstHits.begin(), firstHits.end(),
                                       [](const auto& a, const auto& b) { return a.second < b.second; });
    const auto [kind, index] = most->first;
    if (kind == 1 && index == pigIndex)
        return "the " + bird->name + " bird reaches it, but hit directly it is not defeated (it takes " +
               std::to_string(static_cast<int>(pigType->healthNs)) + " N\u00B7s)";
    if (kind == 1)
        return "the launches that would reach it hit pig " + std::to_string(index) + " first";
    const BlockDef& block = level.blocks[static_cast<std::size_t>(index)];
    const Material* material = catalog.findMaterial(block.material);
    const double momentum = bird->massKg * speed;
    std::string text = "shielded by block " + std::to_string(index) + " (" + block.material + "): the launches that " +
                       "would reach it hit that first";
    if (material != nullptr && material->strengthNs > momentum)
        text += ", and " + block.material + " takes " + std::to_string(static_cast<int>(material->strengthNs)) +
                " N\u00B7s, more than the " + bird->name + " bird's " +
                std::to_string(static_cast<int>(std::lround(momentum))) + " at full pull";
    return text;
}

} // namespace abalike
