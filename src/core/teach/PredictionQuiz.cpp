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

std::optional<double> measuredAnswer(QuizQuantity quantity, const ShotRecord& shot, std::array<double, 2> launchPoint)
{
    const std::vector<std::array<double, 3>>& path = shot.actualPath;
    const double level = launchPoint[1];
    double highest = path.empty() ? level : path.front()[2];
    for (std::size_t i = 1; i < path.size(); ++i)
    {
        // A bird that touched anything on the way flew something else than the formula's flight.
        if (i < shot.actualTouches.size() && !shot.actualTouches[i].empty())
            return std::nullopt;
        const auto& before = path[i - 1];
        const auto& after = path[i];
        highest = std::max(highest, after[2]);
        if (after[2] > level || before[2] <= level)
            continue;
        const double s = (before[2] - level) / (before[2] - after[2]);
        switch (quantity)
        {
        case QuizQuantity::Range:
            return before[1] + s * (after[1] - before[1]) - launchPoint[0];
        case QuizQuantity::FlightTime:
            return before[0] + s * (after[0] - before[0]);
        case QuizQuantity::MaxHeight:
            return highest - level;
        }
    }
    return std::nullopt;
}

} // namespace abalike
