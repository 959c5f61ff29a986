#pragma once

#include "render/Camera.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Window/Event.hpp>
#include <abalike/game/GameSession.hpp>
#include <array>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

/// A point of a recorded path: time since launch, position and velocity.
struct PathSample
{
    double t = 0.0;
    double x = 0.0;
    double y = 0.0;
    double vx = 0.0;
    double vy = 0.0;
};

/// A path the measuring tools can read: a flown shot or the current preview.
struct MeasuredPath
{
    std::string name; ///< "shot 3", "preview"
    std::vector<PathSample> samples;
    sf::Color colour;
};

/// The last several shots' flown paths (kept across restarts until cleared) with PhET's timing dots -- small every
/// 0.1 s, large every 1 s -- and the measuring tools: hover (or click while no bird flies) on any path point for t,
/// x, y, speed and height; a tape measure dragged with the right mouse button between any two points.
class PathHistory
{
public:
    /// Most paths kept; the oldest goes first.
    static constexpr std::size_t kMaxPaths = 5;

    /// A level started or restarted: paths of the same level are kept, another level's are dropped.
    void onLevelStart(const GameSession& session);
    /// Takes in the session's shots (the last one grows while it flies).
    void update(const GameSession& session);
    /// Forgets every path and the tape (key C).
    void clear();
    /// Mouse input for hover, pinning and the tape; true when the event was used.
    bool handleEvent(const sf::Event& event, const Camera& camera, const GameSession& session,
                     const PredictedFlight* preview);

    /// The dots on every kept path, older paths fainter.
    void drawDots(sf::RenderTarget& target, const Camera& camera, float scale) const;
    /// The tape and the hovered or pinned point's readout.
    void drawTools(sf::RenderTarget& target, const sf::Font& font, const Camera& camera, const GameSession& session,
                   unsigned rowSize, float scale) const;

    const std::deque<MeasuredPath>& paths() const { return m_paths; }
    /// True once a path point was read or the tape used.
    bool used() const { return m_used; }

private:
    struct Pick
    {
        std::string path;
        PathSample sample;
    };
    /// The path point nearest to a window position, within a few pixels.
    std::optional<Pick> pick(sf::Vector2f pixel, const Camera& camera, const PredictedFlight* preview,
                             float radiusPx) const;
    /// A window position snapped to a path point if one is near, in world metres.
    sf::Vector2f snap(sf::Vector2f pixel, const Camera& camera, const PredictedFlight* preview) const;

    std::deque<MeasuredPath> m_paths;
    std::string m_levelId;
    std::size_t m_seenShots = 0; ///< shots of the current session already taken in
    bool m_backIsLive = false;   ///< the newest kept path is the session's latest shot, still growing
    int m_shotNumber = 0;        ///< shots recorded since the last clear
    std::optional<Pick> m_hover;
    bool m_pinned = false;
    std::optional<std::array<sf::Vector2f, 2>> m_tape; ///< ends in world metres
    bool m_taping = false;
    bool m_used = false;
};

/// Samples of a flown path (t, x, y per step) with velocities from central differences.
std::vector<PathSample> samplesOf(const std::vector<std::array<double, 3>>& path);

} // namespace abalike::app
