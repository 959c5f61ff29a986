#include <abalike/flight/Prediction.hpp>
#include <algorithm>
#include <cmath>

namespace abalike
{

namespace
{

/// The parts of the state a crossing is located on.
double height(const FlightState& s)
{
    return s.position.y;
}
double verticalSpeed(const FlightState& s)
{
    return s.velocity.y;
}

/// Time in [lo, hi] (inside the step) where a part of the interpolated state crosses `level`, by bisection on the
/// Hermite interpolant. The caller guarantees a sign change between lo and hi.
double locateCrossing(const FlightStep& step, double (*part)(const FlightState&), double level, double lo, double hi)
{
    const bool risingAtLo = part(step.interpolate(lo)) - level < 0.0;
    for (int iteration = 0; iteration < 200 && hi - lo > 0.0; ++iteration)
    {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi)
            break;
        const bool belowAtMid = part(step.interpolate(mid)) - level < 0.0;
        if (belowAtMid == risingAtLo)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

/// Time in [step.t0, step.t1] where component i of the interpolated state crosses `level`, by bisection on the
/// Hermite interpolant. The caller guarantees a sign change between the step's ends.
double locateCrossing(const FlightStep& step, double (*part)(const FlightState&), double level)
{
    return locateCrossing(step, part, level, step.t0, step.t1);
}

/// Raises maxHeight to the highest point of the step up to time `until` (the apex if vy changes sign before it).
void trackApex(const FlightStep& step, double& maxHeight, double until)
{
    if (step.s0.velocity.y > 0.0 && step.s1.velocity.y <= 0.0)
    {
        const double tApex = locateCrossing(step, verticalSpeed, 0.0);
        if (tApex <= until)
            maxHeight = std::max(maxHeight, step.interpolate(tApex).position.y);
    }
}

} // namespace

PredictedFlight predictFlight(const FlightModel& model, const IntegratorSettings& settings, const FlightState& s0,
                              const PredictionLimits& limits)
{
    FlightIntegrator integrator(model, settings);
    integrator.reset(0.0, s0);

    PredictedFlight flight;
    flight.path.emplace_back(0.0, s0);
    flight.maxHeightM = s0.position.y;
    const double landingY = limits.landingY.value_or(s0.position.y);
    const double endTime = limits.untilTimeS ? *limits.untilTimeS : limits.maxTimeS;
    // A step count limit as well as a time limit, so a rounding step never leaves the loop spinning.
    const auto maxSteps = static_cast<std::size_t>(std::ceil(endTime / settings.dtS)) + 1;

    while (flight.steps < maxSteps)
    {
        if (flight.path.back().timeS >= endTime)
        {
            flight.end = FlightEnd::TimeUp;
            break;
        }
        const FlightStep& step = integrator.step();
        ++flight.steps;
        if (!isFinite(step.s1))
        {
            // Every input was finite, but the forces overflowed: stop at the last finite point and say so.
            flight.end = FlightEnd::Diverged;
            break;
        }

        if (limits.contact)
        {
            if (const auto fraction = limits.contact(step.s0, step.s1))
            {
                // The world moves the bird along the chord of each step, so contact is on the chord.
                const double a = std::clamp(*fraction, 0.0, 1.0);
                const double t = step.t0 + a * (step.t1 - step.t0);
                FlightState s = step.interpolate(t);
                s.position.x = step.s0.position.x + a * (step.s1.position.x - step.s0.position.x);
                s.position.y = step.s0.position.y + a * (step.s1.position.y - step.s0.position.y);
                flight.path.emplace_back(t, s);
                flight.contact = ContactPoint{t, s.position.x, s.position.y};
                trackApex(step, flight.maxHeightM, t);
                flight.maxHeightM = std::max(flight.maxHeightM, s.position.y);
                flight.end = FlightEnd::Contact;
                break;
            }
        }
        if (step.t1 >= endTime)
        {
            const FlightState s = step.t1 == endTime ? step.s1 : step.interpolate(endTime);
            trackApex(step, flight.maxHeightM, endTime);
            flight.maxHeightM = std::max(flight.maxHeightM, s.position.y);
            flight.path.emplace_back(endTime, s);
            flight.end = FlightEnd::TimeUp;
            break;
        }
        std::optional<double> landing;
        if (limits.stopOnLanding && !limits.untilTimeS && step.s1.position.y - landingY <= 0.0)
        {
            if (step.s0.position.y - landingY > 0.0)
                landing = locateCrossing(step, height, landingY);
            else if (step.s0.position.y == landingY && step.f0.position.y > 0.0 && step.s1.velocity.y <= 0.0)
            {
                // Launched upwards from the landing height and already back below it at the step's end (a slow
                // launch): both ends are at or below it, so bracket the descent from the apex inside the step.
                const double apex = locateCrossing(step, verticalSpeed, 0.0);
                if (step.interpolate(apex).position.y > landingY)
                    landing = locateCrossing(step, height, landingY, apex, step.t1);
            }
        }
        if (landing)
        {
            const double t = *landing;
            FlightState s = step.interpolate(t);
            s.position.y = landingY; // the crossing is where y == landingY, by definition
            trackApex(step, flight.maxHeightM, t);
            flight.path.emplace_back(t, s);
            flight.end = FlightEnd::Landed;
            break;
        }
        trackApex(step, flight.maxHeightM, step.t1);
        flight.maxHeightM = std::max(flight.maxHeightM, step.s1.position.y);
        flight.path.emplace_back(step.t1, step.s1);
    }

    flight.rhsEvaluations = integrator.rhsEvaluations(); // counted from reset(), including the launch derivative
    flight.substeps = integrator.substeps();
    flight.maxStiffnessRatio = integrator.maxStiffnessRatio();
    flight.guard = integrator.guardAction();
    return flight;
}

} // namespace abalike
