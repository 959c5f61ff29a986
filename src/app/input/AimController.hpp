#pragma once

#include <optional>

#include "render/Camera.hpp"

#include <SFML/Window/Event.hpp>

namespace abalike::app
{

/// The player's aim: an angle and a power (fraction of the slingshot's maximum force), set by dragging the bird
/// back with the mouse or with the arrow keys. Both edit the same state, so the bird, the preview and the
/// readout always agree.
class AimController
{
public:
    static constexpr double kMaxPullM = 2.0;  ///< a full pull: the bird this far behind the pouch is 100% power
    static constexpr double kMinPullM = 0.25; ///< shorter drags are taken as a change of mind, not a shot
    static constexpr double kDefaultAngleDeg = 45.0;
    static constexpr double kDefaultPower = 0.5;
    static constexpr double kMaxAngleDeg = 90.0; ///< keys aim between straight down and straight up

    AimController() { reset(); }

    /// Back to 45 degrees at 50% power, not dragging.
    void reset();
    /// The bird at rest in the pouch (no pull) at the default angle: the genre's start for each new bird.
    void rest();
    /// Sets the aim directly (scripted shots); power is clamped to 0..1.
    void set(double angleDeg, double powerFraction);

    /// Handles mouse and keyboard input while a bird is ready; `pouch` is where the bird leaves the slingshot.
    /// Arrows step the angle by 0.5° and the power by 1 % (Shift: 5° and 10 %; Alt: 0.1° and 0.2 %). A drag sets the
    /// power by its length on the screen: fullPullPx() (render/PullReach.hpp) is a full pull, at any zoom. Losing the
    /// window's focus cancels a drag. Returns true when the player let go of a drag or pressed Space or Enter: launch
    /// with the current aim.
    bool handleEvent(const sf::Event& event, const Camera& camera, sf::Vector2f pouch);

    /// Whether a left press at this window pixel takes hold of the bird (near the pouch or the bird).
    bool grabs(sf::Vector2f pixel, const Camera& camera, sf::Vector2f pouch) const;
    /// Where the bird is drawn and how big it is (world metres): a press within 1.5 bird radii of it, and never less
    /// than kBirdGrabMinPx, takes hold of it too, wherever the pull left it.
    void setBird(std::optional<sf::Vector2f> centre, float radiusM)
    {
        m_birdCentre = centre;
        m_birdRadiusM = radiusM;
    }
    static constexpr float kBirdGrabMinPx = 24.0f;

    double angleDeg() const { return m_angleDeg; }
    double powerFraction() const { return m_power; }
    bool dragging() const { return m_dragging; }
    /// Where the bird sits relative to the pouch: pulled back against the launch direction by the power.
    sf::Vector2f pullOffset() const;

    /// The next multiple of step above (direction > 0) or below the value: keyboard steps land on round numbers.
    static double stepOnGrid(double value, double step, int direction);

private:
    std::optional<sf::Vector2f> m_birdCentre;
    float m_birdRadiusM = 0.0f;
    enum class Step
    {
        Normal,
        Coarse, ///< Shift
        Fine,   ///< Alt
    };
    bool handleKey(sf::Keyboard::Key key, Step size);
    void aimFromPointer(sf::Vector2f pointerPx, sf::Vector2f pouchPx, float fullPullLengthPx);

    double m_angleDeg = kDefaultAngleDeg;
    double m_power = kDefaultPower;
    bool m_dragging = false;
    bool m_dragMoved = false;
    double m_angleBeforeDrag = kDefaultAngleDeg;
    double m_powerBeforeDrag = kDefaultPower;
};

} // namespace abalike::app
