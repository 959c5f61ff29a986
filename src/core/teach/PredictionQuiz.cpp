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
        return launch.launchHeightM + (vy > 0.0 ? vy * vy / (2.0 * g) : 0.0);
    const double discriminant = vy * vy + 2.0 * g * (launch.launchHeightM - launch.birdRadiusM);
    if (discriminant < 0.0)
        return std::nullopt;
    const double time = (vy + std::sqrt(discriminant)) / g;
    return quantity == QuizQuantity::FlightTime ? time : vx * time;
}

std::optional<double> measuredAnswer(QuizQuantity quantity, const ShotRecord& shot, double launchX, double groundY,
                                     double birdRadiusM)
{
    const std::vector<std::array<double, 3>>& path = shot.actualPath;
    if (path.empty())
        return std::nullopt;
    // The touchdown: the first step whose centre is at or below ground + r, after the path has been above it.
    const double touch = groundY + birdRadiusM;
    double highest = path.front()[2];
    for (std::size_t i = 1; i < path.size(); ++i)
    {
        const auto& before = path[i - 1];
        const auto& after = path[i];
        highest = std::max(highest, after[2]);
        if (after[2] > touch || before[2] <= touch)
            continue;
        const double s = (before[2] - touch) / (before[2] - after[2]);
        switch (quantity)
        {
        case QuizQuantity::Range:
            return before[1] + s * (after[1] - before[1]) - launchX;
        case QuizQuantity::FlightTime:
            return before[0] + s * (after[0] - before[0]);
        case QuizQuantity::MaxHeight:
            return highest - groundY;
        }
    }
    return std::nullopt;
}

} // namespace abalike
