#pragma once

#include "play/PlayLayer.hpp"
#include "render/Camera.hpp"
#include "teach/BirdReadout.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Window/Event.hpp>
#include <abalike/teach/Rk4Walkthrough.hpp>
#include <optional>
#include <vector>

namespace abalike::app
{

/// The RK4 walkthrough (spec 16 and 27.5): the flight paused mid-air (or at launch, while aiming), one RK4 step at a
/// time: k1..k4 drawn as arrows from the points where they are evaluated, their weighted average that makes the
/// step, and every number in a panel. At the physics step (1/60 s) each step also moves the world's bird one step.
class WalkthroughView
{
public:
    bool active() const { return m_walk.has_value(); }
    /// K starts (and leaves) it; while it runs it takes every key: Space, Enter or Right for the next step, [ and ]
    /// for the step size, Esc or K to leave. True when used.
    bool handleEvent(const sf::Event& event, PlayView& view, ShotFollower& follower);
    /// Leaves it (a level started or restarted).
    void stop(PlayView& view);

    void drawWorld(sf::RenderTarget& target, const Camera& camera, float scale) const;
    /// The numbers and a magnified drawing of the step; `top` is the panel's top edge, centred in the window.
    void drawPanel(sf::RenderTarget& target, const sf::Font& font, float top, unsigned titleSize, unsigned rowSize,
                   float scale) const;

private:
    void start(PlayView& view, ShotFollower& follower);
    void next(PlayView& view);
    void recompute();

    int m_dtIndex = 2;
    bool m_followsWorld = false; ///< stepping also steps the world (the bird flies free and dt is the physics step)
    FlightModel m_model;
    double m_tS = 0.0;
    FlightState m_state{};
    int m_stepNumber = 1;
    std::vector<FlightState> m_chain; ///< every state the walkthrough has stepped through
    std::optional<Rk4Walkthrough> m_walk;
};

} // namespace abalike::app
