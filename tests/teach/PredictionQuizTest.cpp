#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/teach/PredictionQuiz.hpp>
#include <abalike/teach/ShotFeedback.hpp>
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
    // Back to the launch height: T = 2 v sin a / g, R = v^2 sin 2a / g, H = v^2 sin^2 a / 2g above the launch.
    const QuizLaunch launch{20.0, 30.0, 9.81};
    const double a = std::numbers::pi / 6.0;
    EXPECT_NEAR(*closedFormAnswer(QuizQuantity::FlightTime, launch), 2.0 * 20.0 * std::sin(a) / 9.81, 1e-12);
    EXPECT_NEAR(*closedFormAnswer(QuizQuantity::Range, launch), 400.0 * std::sin(2.0 * a) / 9.81, 1e-12);
    EXPECT_NEAR(*closedFormAnswer(QuizQuantity::MaxHeight, launch), 400.0 * 0.25 / (2.0 * 9.81), 1e-12);
    // Aimed level or down, the bird never comes back up to its launch height and rises no higher; with no gravity
    // nothing comes back.
    EXPECT_DOUBLE_EQ(*closedFormAnswer(QuizQuantity::MaxHeight, {10.0, -20.0, 9.81}), 0.0);
    EXPECT_FALSE(closedFormAnswer(QuizQuantity::Range, {10.0, -20.0, 9.81}).has_value());
    EXPECT_FALSE(closedFormAnswer(QuizQuantity::FlightTime, {10.0, 0.0, 9.81}).has_value());
    EXPECT_FALSE(closedFormAnswer(QuizQuantity::Range, {10.0, 45.0, 0.0}).has_value());
    EXPECT_STREQ(quizQuantityUnit(QuizQuantity::FlightTime), "s");
}

TEST(PredictionQuiz, TheWorldsFlightMeetsTheClosedFormForEveryQuantity)
{
    // The lesson is in vacuum on flat ground: where the bird's centre comes back through the launch height, and its
    // apex, match the formulas to the step's interpolation error (millimetres), at several aims.
    const LevelDef level = predictLesson();
    for (const double angle : {15.0, 30.0, 45.0, 60.0})
    {
        SCOPED_TRACE(angle);
        const auto session = simulateShots(level, {{angle, 14.0}});
        const ShotRecord& shot = session->shots().at(0);
        const QuizLaunch launch{14.0, angle, level.environment.gravity};
        const auto measured = [&](QuizQuantity q)
        {
            return measuredAnswer(q, shot, session->launchPoint());
        };
        ASSERT_TRUE(measured(QuizQuantity::Range).has_value());
        EXPECT_NEAR(*measured(QuizQuantity::Range), *closedFormAnswer(QuizQuantity::Range, launch), 0.02);
        EXPECT_NEAR(*measured(QuizQuantity::FlightTime), *closedFormAnswer(QuizQuantity::FlightTime, launch), 0.002);
        EXPECT_NEAR(*measured(QuizQuantity::MaxHeight), *closedFormAnswer(QuizQuantity::MaxHeight, launch), 0.002);
    }
}

TEST(PredictionQuiz, TheCardAndTheFeedbackMeasureTheSameDistance)
{
    // One convention: the card's measured range is the distance the feedback sentence gives for the launch height,
    // and the sentence says so in words.
    const LevelDef level = predictLesson();
    const auto session = simulateShots(level, {{40.0, 14.0}});
    const ShotRecord& shot = session->shots().at(0);
    const std::string sentence = shotFeedback(level, Catalog::builtin(), shot).back();
    const std::string words = "back to the launch height ";
    const std::size_t at = sentence.find(words);
    ASSERT_NE(at, std::string::npos) << sentence;
    const double said = std::stod(sentence.substr(at + words.size()));
    EXPECT_NEAR(said, *measuredAnswer(QuizQuantity::Range, shot, session->launchPoint()), 0.05) << sentence;
}

TEST(PredictionQuiz, ABirdThatTouchedSomethingOnTheWayHasNoMeasurement)
{
    // A stone wall 8 m tall stands 10 m out: the bird hits it on the way up, falls, and passes the launch height
    // only after that contact.
    LevelDef level = predictLesson();
    level.blocks.push_back({BlockShape::Box, "stone", 10.0, 4.0, 1.0, 8.0});
    const auto session = simulateShots(level, {{30.0, 14.0}});
    const ShotRecord& shot = session->shots().at(0);
    EXPECT_FALSE(measuredAnswer(QuizQuantity::Range, shot, session->launchPoint()).has_value());
}
