#pragma once

#include "play/PlayLayer.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <abalike/teach/PredictionQuiz.hpp>
#include <optional>
#include <string>

namespace abalike::app
{

/// The "predict, then launch" lesson (lesson-predict): while aiming the student types a predicted range, maximum
/// height or flight time for the aim shown (Tab picks which) and locks it with Enter; after the launch the card sets
/// the prediction against the value measured on the flown path and the closed form (abalike::closedFormAnswer).
class PredictQuizView
{
public:
    /// Whether the level is the lesson that asks for predictions.
    static bool wanted(const LevelDef& level) { return level.id == "lesson-predict"; }

    void reset();
    /// Typing, Backspace, Tab and Enter while a bird waits; true when the event was the quiz's.
    bool handleEvent(const sf::Event& event, const PlayView& view);
    void update(const GameSession& session, const std::optional<AimReadout>& aim);
    /// Draws the card at the first place from `at` down where it overlaps no panel drawn before it this frame, with
    /// the rows that have room there (ScreenRegions); returns its bounds, empty when not even its title has room.
    sf::FloatRect draw(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f at, unsigned titleSize,
                       unsigned rowSize, float scale) const;

    /// The last comparison, once the bird has come down: prediction, measured, closed form.
    struct Result
    {
        QuizQuantity quantity;
        double predicted;
        double measured;
        double closedForm;
    };
    const std::optional<Result>& result() const { return m_result; }
    bool locked() const { return m_locked.has_value(); }
    /// Predictions compared with a flight since the level started.
    int answered() const { return m_answered; }

private:
    struct Locked
    {
        QuizQuantity quantity;
        double value;
        double angleDeg;
        double speedMps;
        std::size_t shotsBefore; ///< shots on the level when it was locked: the next one answers it
    };

    QuizQuantity m_quantity = QuizQuantity::Range;
    std::string m_typed;
    std::optional<Locked> m_locked;
    std::optional<Result> m_result;
    std::optional<AimReadout> m_aim;
    std::string m_note; ///< one line of what just happened ("aim changed: predict again")
    int m_answered = 0;
};

} // namespace abalike::app
