#pragma once

#include "render/Camera.hpp"
#include "render/CameraFit.hpp"
#include "render/CameraFocus.hpp"

#include <SFML/System/Vector2.hpp>

namespace abalike::app
{

/// The play screen's camera: starts fitted to the level, follows a shot (zooming out as far as needed to keep every
/// bird and the structure it flies at in view), returns home when the world settles, and takes the player's pan and
/// zoom at any time. Smooth, frame-rate independent, and free of SFML windows, so it is tested headless.
class CameraRig
{
public:
    enum class Mode
    {
        Home,    ///< the level's home view (slingshot and every body)
        Follow,  ///< a shot is under way: bird and structure
        Manual,  ///< the player panned or zoomed; kept until the next launch, the world settling, or recentre()
        Opening, ///< a level wider than the home view shows: a pan from its far end to the slingshot
    };

    /// Snaps to the level's home view in a window of this size.
    void reset(const CameraFocus& focus, sf::Vector2u windowSize);
    /// The window changed size: same scale rules, no stretching; the home view is fitted again.
    void resize(sf::Vector2u windowSize);
    /// Moves towards what the focus asks for; frameS is the real time since the last frame.
    void update(const CameraFocus& focus, double frameS);

    /// Drags the world by a pointer movement in pixels (the world follows the pointer).
    void panPixels(sf::Vector2f deltaPx);
    /// Zooms by a factor (> 1 closer) keeping the world point under this window pixel where it is.
    void zoomAt(float factor, sf::Vector2f pixel);
    /// Back to automatic: home, or following if a shot is under way.
    void recentre();
    /// The player took hold of the bird: a camera still on its way home stops where it is (as if panned there), so
    /// that nothing moves under the hand; the next launch takes over as always.
    void holdStill();
    /// On a level wider than its home view (see homeView), pans from the far end of the level to the slingshot over
    /// kOpeningS; any input ends it (skipOpening), and so does a launch. Returns whether it started.
    bool startOpening(const CameraFocus& focus);
    /// Ends the opening pan at the home view at once.
    void skipOpening();
    /// The view while aiming: the whole level when its smallest pig is then drawn at least kMinPigPx tall, else the
    /// slingshot's end of the level at the scale that draws it so; either way with room around the pouch for a full
    /// pull with the mouse in every launch direction of render/PullReach.hpp (the ground line goes up, the view
    /// reaches further left, as far as needed).
    CameraView homeView(const CameraFocus& focus) const;
    /// True when the home view leaves part of the level out (and the level opens with a pan).
    bool homeLeavesLevelOut(const CameraFocus& focus) const;
    /// The camera to draw with this frame. (A shake is FxLayer's: it moves the picture, not the camera.)
    const Camera& camera() const { return m_camera; }
    /// Where the rig looks.
    const CameraView& view() const { return m_view; }
    Mode mode() const { return m_mode; }

    /// Seconds for the view to cover about 63 % of the way to its target while it follows a shot.
    static constexpr double kFollowTimeS = 0.3;
    /// The way back home takes exactly this long and then stops (an exponential ease crept on for about 3 s). It
    /// starts when the focus is settling (nothing moves, or the next bird is due within this time), so the camera is
    /// at rest when the next bird is ready.
    static constexpr double kReturnS = kReturnHomeS;
    /// The opening pan's length.
    static constexpr double kOpeningS = 2.5;

private:
    /// The home view of a box with the ground line this far up the window, before the pull's room is kept.
    struct HomeFit
    {
        CameraView view;
        bool leavesLevelOut = false;
    };
    HomeFit fitHome(const CameraFocus& focus, const WorldBox& box, float groundFromBottom) const;
    /// The home view with the pull's room kept.
    HomeFit homeFit(const CameraFocus& focus) const;
    /// The home view shows every pig the action may still reach.
    bool homeShowsEveryActionPig(const CameraFocus& focus) const;
    /// The focus is settling and the home view shows every pig the action may still reach: time to head home.
    bool homeShowsTheSettling(const CameraFocus& focus) const;
    /// Where the automatic camera wants to be now.
    CameraView target(const CameraFocus& focus) const;
    /// The shot's birds inside the view, whatever the smoothing did: move the least, zoom out only if needed.
    void keepInView(const CameraFocus& focus);
    /// Manual views stay near the level and within the scale limits.
    void clampManual();
    void rebuild();
    /// Starts the way back home from where the view is now.
    void startReturn();

    CameraView m_view;
    Camera m_camera = Camera::centredOn({0.0f, 0.0f}, 1.0f, {1, 1});
    sf::Vector2u m_window{1, 1};
    WorldBox m_home;
    float m_groundY = 0.0f;
    Mode m_mode = Mode::Home;
    bool m_shotUnderWay = false;
    bool m_settledEarly = false; ///< headed home while the shot was still under way (CameraFocus::settling)
    bool m_snap = true;          ///< jump to the next target instead of easing (new level, resize in home view)
    double m_openingS = 0.0;     ///< time into the opening pan
    CameraView m_openingFrom;
    double m_returnS = kReturnS; ///< time into the way back home
    CameraView m_returnFrom;
    CameraView m_returnGoal; ///< the home view it heads for: a new one (the banner moved the ground) starts again
};

} // namespace abalike::app
