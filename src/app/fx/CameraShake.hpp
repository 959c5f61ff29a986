#pragma once

#include <SFML/System/Vector2.hpp>

namespace abalike::app
{

/// A short shake of the world view when something heavy breaks or a bird explodes. Kicks add up to a cap and die
/// away in a fraction of a second; the offset is a sum of two sines per axis, so it is the same for the same kicks
/// and frame times (screenshots stay reproducible). Visual only: the physics never sees it.
class CameraShake
{
public:
    static constexpr float kMaxPx = 16.0f;   ///< at a UI scale of 1
    static constexpr double kDecayS = 0.12;  ///< the amplitude falls by e in this time
    static constexpr float kStillPx = 0.25f; ///< below this the shake is over

    /// Adds a kick of this many pixels (at a UI scale of 1).
    void kick(float amplitudePx);
    /// Advances the shake by one frame.
    void update(double frameS);
    /// Stops at once (level restart).
    void reset();
    /// Where the world is drawn from its resting place, in pixels at a UI scale of 1.
    sf::Vector2f offsetPx() const;
    bool active() const { return m_amplitudePx > 0.0f; }

private:
    float m_amplitudePx = 0.0f;
    double m_timeS = 0.0;
};

} // namespace abalike::app
