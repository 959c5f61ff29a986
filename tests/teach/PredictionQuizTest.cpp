#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/teach/PredictionQuiz.hpp>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <string>

using namespace abalike;

namespace
{

LevelDef predictLesson()
{
    return loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/lessons/lesson-predict.json", Catalog::builtin());
}

} // namespace

TEST(PredictionQuiz, ClosedFormsAreTheTextbookOnes)
{
    // From the ground to the ground: T = 2 v sin a / g, R = v^2 sin 2a / g, H = v^2 sin^2 a / 2g.
    const QuizLaunch ground{20.0, 30.0, 9.81, 0.0, 0.0};
    const double a = std::numbers::pi / 6.0;
    EXPECT_NEAR(*closedFormAnswer(QuizQuantity::FlightTime, ground), 2.0 * 20.0 * std::sin(a) / 9.81, 1e-12);
    EXPECT_NEAR(*closedFormAnswer(QuizQuantity::Range, ground), 400.0 * std::sin(2.0 * a) / 9.81, 1e-12);
    EXPECT_NEAR(*closedFormAnswer(QuizQuantity::MaxHeight, ground), 400.0 * 0.25 / (2.0 * 9.81), 1e-12);
    // Aimed down from a height, the highest point is the launch; with no gravity nothing lands.
    EXPECT_DOUBLE_EQ(*closedFormAnswer(QuizQuantity::MaxHeight, {10.0, -20.0, 9.81, 5.0, 0.25}), 5.0);
    EXPECT_FALSE(closedFormAnswer(QuizQuantity::Range, {10.0, 45.0, 0.0, 1.5, 0.25}).has_value());
    EXPECT_STREQ(quizQuantityUnit(QuizQuantity::FlightTime), "s");
}

TEST(PredictionQuiz, TheWorldsFlightMeetsTheClosedFormForEveryQuantity)
{
    // The lesson is in vacuum on flat ground: the measured touchdown and apex match the formulas to the step's
    // interpolation error (millimetres), at several aims.
    const LevelDef level = predictLesson();
    const BirdType& red = *Catalog::builtin().findBird("red");
    for (const double angle : {15.0, 30.0, 45.0, 60.0})
    {
        SCOPED_TRACE(angle);
        const auto session = simulateShots(level, {{angle, 14.0}});
        const ShotRecord& shot = session->shots().at(0);
        const QuizLaunch launch{14.0, angle, level.environment.gravity, level.slingshot.y - level.groundY, red.radiusM};
        const auto measured = [&](QuizQuantity q)
        {
            return measuredAnswer(q, shot, level.slingshot.x, level.groundY, red.radiusM);
        };
        ASSERT_TRUE(measured(QuizQuantity::Range).has_value());
        EXPECT_NEAR(*measured(QuizQuantity::Range), *closedFormAnswer(QuizQuantity::Range, launch), 0.02);
        EXPECT_NEAR(*measured(QuizQuantity::FlightTime), *closedFormAnswer(QuizQuantity::FlightTime, launch), 0.002);
        EXPECT_NEAR(*measured(QuizQuantity::MaxHeight), *closedFormAnswer(QuizQuantity::MaxHeight, launch), 0.002);
    }
}
