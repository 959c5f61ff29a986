#include "teach/PredictQuizView.hpp"

#include "render/ScreenRegions.hpp"

#include "render/TextFormat.hpp"
#include "teach/TeachDraw.hpp"

#include <cmath>
#include <cstdlib>

namespace abalike::app
{

namespace
{
constexpr std::size_t kMaxTyped = 8;

QuizQuantity next(QuizQuantity quantity)
{
    switch (quantity)
    {
    case QuizQuantity::Range:
        return QuizQuantity::MaxHeight;
    case QuizQuantity::MaxHeight:
        return QuizQuantity::FlightTime;
    case QuizQuantity::FlightTime:
        break;
    }
    return QuizQuantity::Range;
}

bool isDigitKey(sf::Keyboard::Key key)
{
    return (key >= sf::Keyboard::Num0 && key <= sf::Keyboard::Num9) ||
           (key >= sf::Keyboard::Numpad0 && key <= sf::Keyboard::Numpad9) || key == sf::Keyboard::Period;
}

/// Times to the millisecond (a flight's time differs from the formula's in the third decimal), lengths to the cm.
int quantityDecimals(QuizQuantity quantity)
{
    return quantity == QuizQuantity::FlightTime ? 3 : 2;
}

std::string withQuantityUnit(double value, QuizQuantity quantity)
{
    return withUnit(value, quantityDecimals(quantity), quizQuantityUnit(quantity));
}
} // namespace

void PredictQuizView::reset()
{
    m_answered = 0;
    m_typed.clear();
    m_locked.reset();
    m_result.reset();
    m_note.clear();
}

bool PredictQuizView::handleEvent(const sf::Event& event, const PlayView& view)
{
    if (!wanted(view.session().level()) || view.session().phase() != Phase::Aiming)
        return false;
    if (event.type == sf::Event::TextEntered)
    {
        const sf::Uint32 c = event.text.unicode;
        if ((c >= '0' && c <= '9') || c == '.')
        {
            if (!m_locked && m_typed.size() < kMaxTyped && !(c == '.' && m_typed.find('.') != std::string::npos))
                m_typed += static_cast<char>(c);
            return true;
        }
        return false;
    }
    if (event.type != sf::Event::KeyPressed || event.key.control || event.key.alt)
        return false;
    const sf::Keyboard::Key key = event.key.code;
    if (isDigitKey(key))
        return true; // the text event types it; the key must not also move the camera (0 is Home)
    if (key == sf::Keyboard::BackSpace)
    {
        if (m_locked)
            m_locked.reset();
        else if (!m_typed.empty())
            m_typed.pop_back();
        return true;
    }
    if (key == sf::Keyboard::Tab)
    {
        m_quantity = next(m_quantity);
        m_locked.reset();
        m_typed.clear();
        return true;
    }
    // Enter locks a typed prediction; once locked, Enter and Space launch as always.
    if ((key == sf::Keyboard::Enter) && !m_locked && !m_typed.empty() && m_aim)
    {
        m_locked = Locked{m_quantity, std::strtod(m_typed.c_str(), nullptr), m_aim->angleDeg, m_aim->speedMps,
                          view.session().shots().size()};
        m_result.reset();
        m_note.clear();
        return true;
    }
    return false;
}

void PredictQuizView::update(const GameSession& session, const std::optional<AimReadout>& aim)
{
    if (!wanted(session.level()))
        return;
    m_aim = aim;
    // A prediction is for the aim shown: changing the aim after locking asks for a new one.
    if (m_locked && aim && session.shots().size() == m_locked->shotsBefore &&
        (std::abs(aim->angleDeg - m_locked->angleDeg) > 1e-9 || std::abs(aim->speedMps - m_locked->speedMps) > 1e-9))
    {
        m_locked.reset();
        m_note = "The aim changed: predict again for the new aim.";
    }
    if (!m_locked || session.shots().size() <= m_locked->shotsBefore)
        return;
    const ShotRecord& shot = session.shots()[m_locked->shotsBefore];
    const std::optional<double> measured = measuredAnswer(m_locked->quantity, shot, session.launchPoint());
    const QuizLaunch launch{shot.speedMps, shot.angleDeg, session.level().environment.gravity};
    const std::optional<double> closed = closedFormAnswer(m_locked->quantity, launch);
    if (measured && closed)
    {
        m_result = Result{m_locked->quantity, m_locked->value, *measured, *closed};
        ++m_answered;
        m_locked.reset();
        m_typed.clear();
    }
    else if (session.phase() == Phase::Aiming || session.finished())
    {
        // The bird hit something before it came back down to its launch height: nothing to compare.
        m_note = "That bird did not come back down to its launch height freely: no measurement. Predict again.";
        m_locked.reset();
    }
}

sf::FloatRect PredictQuizView::draw(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f at, unsigned titleSize,
                                    unsigned rowSize, float scale) const
{
    std::vector<PanelRow> rows;
    const std::string what = quizQuantityName(m_quantity);
    if (m_aim)
        rows.push_back(
            {"aim shown", formatFixed(m_aim->angleDeg, 1) + "\u00B0 at " + withUnit(m_aim->speedMps, 1, "m/s")});
    if (m_locked)
    {
        rows.push_back({"your " + std::string(quizQuantityName(m_locked->quantity)),
                        withQuantityUnit(m_locked->value, m_locked->quantity) + "  (locked)"});
        rows.push_back({"Launch at this aim: Space, or let go of the bird.", ""});
    }
    else
    {
        rows.push_back({"your " + what + " (type it)",
                        (m_typed.empty() ? std::string("_") : m_typed + "_") + " " + quizQuantityUnit(m_quantity)});
        rows.push_back({"Enter locks it; Tab: range, height or time.", ""});
    }
    if (!m_note.empty())
        rows.push_back({m_note, ""});
    if (m_result)
    {
        const Result& r = *m_result;
        const double error = r.predicted - r.measured;
        rows.push_back({"last shot: " + std::string(quizQuantityName(r.quantity)), "", sf::Color::Transparent, true});
        rows.push_back({"  you predicted", withQuantityUnit(r.predicted, r.quantity)});
        rows.push_back({"  measured on the flight", withQuantityUnit(r.measured, r.quantity)});
        rows.push_back({"  the formula gives", withQuantityUnit(r.closedForm, r.quantity)});
        rows.push_back({r.quantity == QuizQuantity::MaxHeight ? "  (its centre, above the launch height)"
                                                              : "  (until its centre is back at the launch height)",
                        ""});
        rows.push_back(
            {"  your error", formatSigned(error, quantityDecimals(r.quantity)) + " " + quizQuantityUnit(r.quantity) +
                                 " (" + formatSigned(r.measured != 0.0 ? 100.0 * error / r.measured : 0.0, 1) + " %)"});
    }
    // It goes down past the panels above it by its own width (narrower than its column, it often fits beside a wide
    // panel of the other column). In a window too small for the whole card it keeps the rows that have room (the aim
    // and the typed answer come first); with no room even for its title it is left out. The same while it would cover a
    // pig, the flying bird or where the last shot struck (the bird flies under it after the launch).
    for (;;)
    {
        const TextPanel panel("Predict, then launch", rows);
        const sf::Vector2f size = panel.measure(font, titleSize, rowSize, scale);
        const sf::Vector2f place(at.x, firstFreeTop(at.x, size.x, at.y, size.y, 6.0f * scale));
        if (panelHasRoom(target, {place, size}) && !coversKeptInView({place, size}, true, false))
            return panel.draw(target, font, place, titleSize, rowSize, scale);
        if (rows.empty())
            return {};
        rows.pop_back();
    }
}

} // namespace abalike::app
