#pragma once

#include "render/CameraFit.hpp"
#include "render/WorldBox.hpp"

#include <SFML/System/Vector2.hpp>
#include <abalike/game/GameSession.hpp>
#include <optional>
#include <vector>

namespace abalike::app
{

/// What the camera should keep in view this frame, in world metres. Plain values, so the camera's logic is tested
/// without a window (tests/app/CameraRigTest.cpp).
struct CameraFocus
{
    WorldBox home;                     ///< the level as designed: the view it starts with and returns to
    float groundY = 0.0f;              ///< the ground line, kept near the bottom edge
    bool shotUnderWay = false;         ///< a bird was launched and the world has not settled yet
    std::vector<WorldBox> birds;       ///< every bird, split bird and egg in the world, launched bird first
    sf::Vector2f birdVelocityMps;      ///< the launched bird's velocity (the camera leads it)
    std::optional<WorldBox> structure; ///< the standing blocks and pigs the shot is flying at
    float birdDiameterM = 0.0f;        ///< the launched bird's size: in flight it is never drawn under kMinBirdPx
    /// From the shot's first contact until the next bird is ready the camera frames the action, not the bird: every
    /// moving block and pig, and every live pig within kActionReachM of one.
    bool afterImpact = false;
    std::vector<WorldBox> action;     ///< the moving bodies and the pigs near them
    std::vector<WorldBox> actionPigs; ///< of those, the live pigs: they must stay inside the window
    /// After the impact, nothing moves fast any more (the world is about to be calm): the camera may head home, so
    /// that it is at rest when the next bird is ready.
    bool settling = false;
    /// After the impact, the next bird is due within kReturnHomeS (GameSession::kReadyAfterContactS): the camera
    /// heads home whatever still moves.
    bool birdDue = false;
    float topReserved = camera_limits::kTopReserved; ///< the window's top fraction panels cover
    /// Where the ground line sits, as a fraction of the window up from its bottom: higher when the text at the bottom
    /// (the keys, the hint) reaches above the usual place, at large text sizes.
    float groundFromBottom = camera_limits::kGroundFromBottom;
    /// The smallest pig of the level as designed (its diameter): the view while aiming never draws it under
    /// kMinPigPx, showing the slingshot and as much of the level as fits instead of all of it.
    float smallestPigM = 0.0f;
    /// Where the bird sits in the slingshot: the view while aiming keeps room around it for a full pull with the mouse
    /// (render/PullReach.hpp). None: no room is kept (a focus made up by hand).
    std::optional<sf::Vector2f> pouchM;
};

/// While aiming, a small pig is drawn at least this tall: wider levels show the slingshot's end of the level and
/// open with a pan over the rest.
inline constexpr float kMinPigPx = 12.0f;

/// The way home (to the aiming view) takes this long, then the camera stops.
inline constexpr double kReturnHomeS = 0.5;

/// A pig this near a moving body may be hit by it: the camera keeps it in view after an impact.
inline constexpr float kActionReachM = 15.0f;
/// The launched bird is never drawn smaller than this across in flight: the camera follows it rather than keep
/// everything in view.
inline constexpr float kMinBirdPx = 12.0f;

/// The focus of a session as it is now: the launched bird, the structure between it and where it was aimed (the
/// predicted first contact), or, once it has landed, what stands around it.
CameraFocus cameraFocusOf(const GameSession& session);

} // namespace abalike::app
