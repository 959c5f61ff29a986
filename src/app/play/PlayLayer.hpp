#pragma once

#include "play/SlowMotion.hpp"
#include "render/Camera.hpp"
#include "render/Hud.hpp"

#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Window/Event.hpp>
#include <abalike/flight/Prediction.hpp>
#include <abalike/game/GameSession.hpp>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace abalike::app
{

class ShotTrails;

class AppContext;

/// What a layer on the play screen can see and do. The play screen implements it.
class PlayView
{
public:
    virtual ~PlayView() = default;

    virtual AppContext& app() = 0;
    /// Game or learn: what this level shows (the tutorial and the lessons are always learn).
    virtual PlayMode playMode() const = 0;
    /// What the player calls this level: a campaign level's number ("2-6"), else the level's id.
    virtual std::string levelLabel() const = 0;
    virtual const GameSession& session() const = 0;
    virtual const Camera& camera() const = 0;
    /// The RK4 preview of the current aim while aiming, else null.
    virtual const PredictedFlight* preview() const = 0;
    /// The current aim while a bird waits in the slingshot.
    virtual std::optional<AimReadout> aim() const = 0;

    /// The paths the last shots on this level flew (kept across restarts).
    virtual const ShotTrails& trails() const = 0;
    /// Forgets them (key C).
    virtual void clearTrails() = 0;

    /// While frozen the play screen takes no physics steps (the RK4 walkthrough pauses a flight this way).
    virtual bool frozen() const = 0;
    virtual void setFrozen(bool frozen) = 0;
    /// Takes one physics step now, frozen or not.
    virtual void stepOnce() = 0;
    /// How fast the world is shown (key Z): fewer physics steps per frame, never a different step.
    virtual SlowMotion& slowMotion() = 0;
};

/// Something drawn over the play screen and given its input first: the teaching overlay, path history, tools.
/// Layers are made once per play screen (layers/PlayLayerTable.hpp) and kept across restarts and levels.
class PlayLayer
{
public:
    virtual ~PlayLayer() = default;

    virtual std::string_view name() const = 0;
    /// Offered every event before the play screen sees it (top layer first); true consumes it.
    virtual bool handleEvent(const sf::Event& event, PlayView& view)
    {
        (void)event;
        (void)view;
        return false;
    }
    /// A level started or restarted.
    virtual void onLevelStart(PlayView& view) { (void)view; }
    /// After each physics step.
    virtual void afterStep(PlayView& view) { (void)view; }
    /// Once per frame before drawing, with the frame's real duration.
    virtual void frameUpdate(PlayView& view, double frameS)
    {
        (void)view;
        (void)frameS;
    }
    /// Drawn with the world, after the bodies and before the HUD, in window pixels (use view.camera()).
    virtual void drawWorld(sf::RenderTarget& target, PlayView& view)
    {
        (void)target;
        (void)view;
    }
    /// This layer asks that the preview be left out this frame (a lesson's prediction not yet locked in).
    virtual bool hidesPreview(const PlayView& view) const
    {
        (void)view;
        return false;
    }
    /// How far this layer shakes the world's picture this frame, in window pixels (the HUD stays still).
    virtual sf::Vector2f worldShakePx(PlayView& view) const
    {
        (void)view;
        return {0.0f, 0.0f};
    }
    /// Drawn over the HUD, in window pixels (panels, charts).
    virtual void drawScreen(sf::RenderTarget& target, PlayView& view)
    {
        (void)target;
        (void)view;
    }
};

} // namespace abalike::app
