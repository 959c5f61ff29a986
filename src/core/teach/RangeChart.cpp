#include <abalike/flight/Prediction.hpp>
#include <abalike/teach/RangeChart.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace abalike
{

namespace
{

/// The refined best angle is within this of the true optimum of the integrated range (golden-section bracket).
constexpr double kBestAngleBracketDeg = 0.005;

/// Range as a number to maximise: a flight that never lands ranks below every one that does.
double rankedRange(const RangeLaunch& launch, double angleDeg)
{
    return rangeAtAngle(launch, angleDeg).value_or(-std::numeric_limits<double>::infinity());
}

} // namespace

std::optional<double> rangeAtAngle(const RangeLaunch& launch, double angleDeg)
{
    const FlightState s0 = launchState(0.0, launch.heightM, launch.speedMps, angleDeg);
    // From the ground, a launch that does not point upwards is in the ground already.
    if (launch.heightM <= 0.0 && !(s0.velocity.y > 0.0))
        return 0.0;
    PredictionLimits limits;
    limits.maxTimeS = launch.maxTimeS;
    limits.stopOnLanding = true;
    limits.landingY = 0.0;
    const PredictedFlight flight = predictFlight(launch.model, launch.settings, s0, limits);
    if (flight.end != FlightEnd::Landed)
        return std::nullopt;
    return flight.path.back().state.position.x - s0.position.x;
}

RangeChart rangeChart(const RangeLaunch& launch, double fromDeg, double toDeg, double stepDeg)
{
    if (!std::isfinite(fromDeg) || !std::isfinite(toDeg) || fromDeg < -90.0 || toDeg > 90.0 || fromDeg > toDeg)
        throw std::invalid_argument("the angles must satisfy -90 <= from <= to <= 90 degrees");
    if (!(stepDeg > 0.0) || !std::isfinite(stepDeg))
        throw std::invalid_argument("the angle step must be a finite number > 0 degrees");
    if (!std::isfinite(launch.speedMps) || launch.speedMps < 0.0)
        throw std::invalid_argument("the launch speed must be a finite number >= 0 m/s");
    if (!std::isfinite(launch.heightM) || launch.heightM < 0.0)
        throw std::invalid_argument("the launch height must be a finite number >= 0 m (the ground is y = 0)");
    if (!(launch.maxTimeS > 0.0) || !std::isfinite(launch.maxTimeS))
        throw std::invalid_argument("the longest flight time must be a finite number > 0 s");
    if (const std::string problem = validateFlightModel(launch.model); !problem.empty())
        throw std::invalid_argument(problem);
    // A tolerance of a millionth of a step, so that -90..90 in steps of 0.1 ends at 90 despite rounding.
    const double intervals = std::floor((toDeg - fromDeg) / stepDeg + 1e-6);
    if (intervals + 1.0 > static_cast<double>(kMaxRangeChartAngles))
        throw std::invalid_argument("the chart would have more than " + std::to_string(kMaxRangeChartAngles) +
                                    " angles; use a larger step");

    RangeChart chart;
    const auto count = static_cast<std::size_t>(intervals) + 1;
    std::size_t best = count;
    double bestRange = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < count; ++i)
    {
        const double angle = std::min(toDeg, fromDeg + static_cast<double>(i) * stepDeg);
        const std::optional<double> range = rangeAtAngle(launch, angle);
        chart.anglesDeg.push_back(angle);
        chart.rangesM.push_back(range);
        if (range && *range > bestRange)
        {
            best = i;
            bestRange = *range;
        }
    }
    if (best == count)
        return chart;

    // The optimum lies within a grid step of the best sample: golden-section search there, on the same integrated
    // and interpolated landing as the samples.
    double lo = std::max(fromDeg, chart.anglesDeg[best] - stepDeg);
    double hi = std::min(toDeg, chart.anglesDeg[best] + stepDeg);
    const double invPhi = (std::sqrt(5.0) - 1.0) / 2.0;
    double a = hi - invPhi * (hi - lo);
    double b = lo + invPhi * (hi - lo);
    double fa = rankedRange(launch, a);
    double fb = rankedRange(launch, b);
    while (hi - lo > kBestAngleBracketDeg)
    {
        if (fa >= fb)
        {
            hi = b;
            b = a;
            fb = fa;
            a = hi - invPhi * (hi - lo);
            fa = rankedRange(launch, a);
        }
        else
        {
            lo = a;
            a = b;
            fa = fb;
            b = lo + invPhi * (hi - lo);
            fb = rankedRange(launch, b);
        }
    }
    const double refined = 0.5 * (lo + hi);
    const double refinedRange = rankedRange(launch, refined);
    // On a flat optimum (every angle lands at 0, say) the search wanders; keep the sample unless it truly improves.
    if (refinedRange > bestRange)
    {
        chart.bestAngleDeg = refined;
        chart.bestRangeM = refinedRange;
    }
    else
    {
        chart.bestAngleDeg = chart.anglesDeg[best];
        chart.bestRangeM = bestRange;
    }
    return chart;
}

} // namespace abalike
