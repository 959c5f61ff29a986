#include <abalike/teach/PredictionQuiz.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace abalike
{

const char* quizQuantityName(QuizQuantity quantity)
{
    switch (quantity)
    {
    case QuizQuantity::Range:
        return "range";
    case QuizQuantity::MaxHeight:
        return "maximum height";
    case QuizQuantity::FlightTime:
        return "flight time";
    }
    return "";
}

const char* quizQuantityUnit(QuizQuantity quantity)
{
    return quantity == QuizQuantity::FlightTime ? "s" : "m";
}

std::optional<double> closedFormAnswer(QuizQuantity quantity, const QuizLaunch& launch)
{
    const double g = launch.gravity;
    if (!(g > 0.0))
        return std::nullopt;
    const double a = launch.angleDeg * std::numbers::pi / 180.0;
    const double vx = launch.speedMps * std::cos(a);
    const double vy = launch.speedMps * std::sin(a);
    if (quantity == QuizQuantity::MaxHeight)
        return vy > 0.0 ? vy * vy / (2.0 * g) : 0.0;
    if (!(vy > 0.0))
        return std::nullopt;
    const double time = 2.0 * vy / g;
    return quantity == QuizQuantity::FlightTime ? time : vx * time;
}

std::optional<double> measuredAnswer(QuizQuantity quantity, const ShotRecord& shot, Vec2 launchPoint)
{
    const std::vector<TrackPoint>& path = shot.actualPath;
    const double level = launchPoint.y;
    double highest = path.empty() ? level : path.front().position.y;
    for (std::size_t i = 1; i < path.size(); ++i)
    {
        // A bird that touched anything on the way flew something else than the formula's flight.
        if (i < shot.actualTouches.size() && !shot.actualTouches[i].empty())
            return std::nullopt;
        const auto& before = path[i - 1];
        const auto& after = path[i];
        highest = std::max(highest, after.position.y);
        if (after.position.y > level || before.position.y <= level)
            continue;
        const double s = (before.position.y - level) / (before.position.y - after.position.y);
        switch (quantity)
        {
        case QuizQuantity::Range:
            return before.position.x + s * (after.position.x - before.position.x) - launchPoint.x;
        case QuizQuantity::FlightTime:
            return before.timeS + s * (after.timeS - before.timeS);
        case QuizQuantity::MaxHeight:
            return highest - level;
        }
    }
    return std::nullopt;
}

} // namespace abalike
