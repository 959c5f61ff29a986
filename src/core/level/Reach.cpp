#include "level/Reach.hpp"

#include <abalike/flight/FlightIntegrator.hpp>

#include <algorithm>

namespace abalike
{

namespace
{
constexpr double kAngleStepDeg = 1.0;
constexpr double kStepS = 1.0 / 60.0; // the world's step: the envelope sees what the game would fly
} // namespace

ReachEnvelope reachEnvelope(const FlightModel& model, double x0, double y0, double speedMps,
                            const std::vector<double>& xs, double floorY, double maxTimeS)
{
    ReachEnvelope out;
    out.highestY.resize(xs.size());
    out.farthestX = x0;
    IntegratorSettings settings;
    settings.dtS = kStepS;
    FlightIntegrator flight(model, settings);
    for (double angle = -90.0; angle <= 90.0 + 1e-9; angle += kAngleStepDeg)
    {
        flight.reset(0.0, launchState(x0, y0, speedMps, angle));
        while (flight.time() < maxTimeS)
        {
            const FlightStep& step = flight.step();
            const double ax = step.s0.position.x;
            const double ay = step.s0.position.y;
            const double bx = step.s1.position.x;
            const double by = step.s1.position.y;
            out.farthestX = std::max(out.farthestX, bx);
            for (std::size_t i = 0; i < xs.size(); ++i)
            {
                const double x = xs[i];
                if ((ax - x) * (bx - x) > 0.0 || ax == bx)
                    continue;
                const double y = ay + (by - ay) * (x - ax) / (bx - ax);
                if (!out.highestY[i] || y > *out.highestY[i])
                    out.highestY[i] = y;
            }
            if (by < floorY && step.s1.velocity.y < 0.0)
                break;
        }
    }
    return out;
}

} // namespace abalike
