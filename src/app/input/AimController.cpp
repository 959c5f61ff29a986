#include "input/AimController.hpp"

#include "render/PullReach.hpp"

#include <abalike/util/Angles.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace abalike::app
{

namespace
{
constexpr double kAngleStepDeg = 0.5;
constexpr double kCoarseAngleStepDeg = 5.0;
constexpr double kFineAngleStepDeg = 0.1;
constexpr double kPowerStep = 0.01;
constexpr double kCoarsePowerStep = 0.10;
constexpr double kFinePowerStep = 0.002;
constexpr float kGrabRadiusM = 1.0f;
constexpr float kGrabRadiusPx = 36.0f;

float distance(sf::Vector2f a, sf::Vector2f b)
{
    return std::hypot(a.x - b.x, a.y - b.y);
}
} // namespace

void AimController::reset()
{
    m_angleDeg = kDefaultAngleDeg;
    m_power = kDefaultPower;
    m_dragging = false;
    m_dragMoved = false;
}

void AimController::rest()
{
    reset();
    m_power = 0.0;
}

void AimController::set(double angleDeg, double powerFraction)
{
    m_angleDeg = angleDeg;
    m_power = std::clamp(powerFraction, 0.0, 1.0);
}

sf::Vector2f AimController::pullOffset() const
{
    const double pull = m_power * kMaxPullM;
    return {static_cast<float>(-pull * std::cos(m_angleDeg * kDegToRad)),
            static_cast<float>(-pull * std::sin(m_angleDeg * kDegToRad))};
}

bool AimController::grabs(sf::Vector2f pixel, const Camera& camera, sf::Vector2f pouch) const
{
    const sf::Vector2f world = camera.toWorld(pixel);
    const float grab = std::max(kGrabRadiusM, kGrabRadiusPx * camera.metresPerPixel());
    // The pointer's pull (where it was let go) counts too: it is where the player's hand is.
    const sf::Vector2f pouchPx = camera.toScreen(pouch);
    const float pullPx = static_cast<float>(m_power) * fullPullPx(camera.windowSize());
    const sf::Vector2f handPx = pouchPx - pullPx * sf::Vector2f(static_cast<float>(std::cos(m_angleDeg * kDegToRad)),
                                                                -static_cast<float>(std::sin(m_angleDeg * kDegToRad)));
    if (m_birdCentre)
    {
        const float birdReach = std::max(kBirdGrabMinPx, 1.5f * m_birdRadiusM * camera.pixelsPerMetre());
        if (distance(pixel, camera.toScreen(*m_birdCentre)) <= birdReach)
            return true;
    }
    return distance(world, pouch) <= grab || distance(world, pouch + pullOffset()) <= grab ||
           distance(pixel, handPx) <= kGrabRadiusPx;
}

bool AimController::handleEvent(const sf::Event& event, const Camera& camera, sf::Vector2f pouch)
{
    switch (event.type)
    {
    case sf::Event::MouseButtonPressed:
    {
        if (event.mouseButton.button != sf::Mouse::Left)
            return false;
        if (grabs({static_cast<float>(event.mouseButton.x), static_cast<float>(event.mouseButton.y)}, camera, pouch))
        {
            m_dragging = true;
            m_dragMoved = false;
            m_angleBeforeDrag = m_angleDeg;
            m_powerBeforeDrag = m_power;
        }
        return false;
    }
    case sf::Event::MouseMoved:
        if (m_dragging)
        {
            m_dragMoved = true;
            aimFromPointer({static_cast<float>(event.mouseMove.x), static_cast<float>(event.mouseMove.y)},
                           camera.toScreen(pouch), fullPullPx(camera.windowSize()));
        }
        return false;
    case sf::Event::MouseButtonReleased:
    {
        if (event.mouseButton.button != sf::Mouse::Left || !m_dragging)
            return false;
        m_dragging = false;
        if (m_dragMoved && m_power * kMaxPullM >= kMinPullM)
            return true;
        // A click or a tiny pull: keep the aim the player had.
        m_angleDeg = m_angleBeforeDrag;
        m_power = m_powerBeforeDrag;
        return false;
    }
    case sf::Event::KeyPressed:
        return handleKey(event.key.code, event.key.shift ? Step::Coarse : event.key.alt ? Step::Fine : Step::Normal);
    case sf::Event::LostFocus:
        // A pull whose button was let go outside the window would follow the cursor with nothing held: the bird
        // goes back to the aim it had, and nothing launches.
        if (m_dragging)
        {
            m_dragging = false;
            m_angleDeg = m_angleBeforeDrag;
            m_power = m_powerBeforeDrag;
        }
        return false;
    default:
        return false;
    }
}

double AimController::stepOnGrid(double value, double step, int direction)
{
    // The next grid point strictly beyond the value, so a dragged 43.2° goes to 44° (or 45° coarse), and repeated
    // presses read as round numbers. The tolerance keeps a value already on the grid from being counted twice.
    const double cells = value / step;
    const double tolerance = 1e-6;
    const double next = direction > 0 ? std::floor(cells + tolerance) + 1.0 : std::ceil(cells - tolerance) - 1.0;
    return next * step;
}

bool AimController::handleKey(sf::Keyboard::Key key, Step size)
{
    if (m_dragging)
        return false;
    const double angleStep = size == Step::Coarse ? kCoarseAngleStepDeg
                             : size == Step::Fine ? kFineAngleStepDeg
                                                  : kAngleStepDeg;
    const double powerStep = size == Step::Coarse ? kCoarsePowerStep : size == Step::Fine ? kFinePowerStep : kPowerStep;
    switch (key)
    {
    case sf::Keyboard::Up:
        m_angleDeg = std::min(stepOnGrid(m_angleDeg, angleStep, +1), kMaxAngleDeg);
        return false;
    case sf::Keyboard::Down:
        m_angleDeg = std::max(stepOnGrid(m_angleDeg, angleStep, -1), -kMaxAngleDeg);
        return false;
    case sf::Keyboard::Right:
        m_power = std::min(stepOnGrid(m_power, powerStep, +1), 1.0);
        return false;
    case sf::Keyboard::Left:
        m_power = std::max(stepOnGrid(m_power, powerStep, -1), kPowerStep);
        return false;
    case sf::Keyboard::Space:
    case sf::Keyboard::Enter:
        return m_power * kMaxPullM >= kMinPullM;
    default:
        return false;
    }
}

void AimController::aimFromPointer(sf::Vector2f pointerPx, sf::Vector2f pouchPx, float fullPullLengthPx)
{
    // The launch goes opposite to the drag, from the pointer through the pouch; the drag's length on the screen is the
    // pull fraction, whatever the zoom (y points down on the screen, up in the world).
    const sf::Vector2f pull = pouchPx - pointerPx;
    const double length = std::hypot(pull.x, pull.y);
    if (length < 1e-3)
    {
        m_power = 0.0;
        return;
    }
    m_angleDeg = std::atan2(-pull.y, pull.x) / kDegToRad;
    m_power = std::min(length / fullPullLengthPx, 1.0);
}

} // namespace abalike::app
