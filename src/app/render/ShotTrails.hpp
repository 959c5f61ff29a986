#pragma once

#include <SFML/Graphics/Color.hpp>
#include <abalike/game/GameSession.hpp>
#include <array>
#include <cstddef>
#include <deque>
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

/// A path the player can look back at and measure: a flown shot or the current preview.
struct MeasuredPath
{
    std::string name; ///< "shot 3", "preview"
    std::vector<PathSample> samples;
    sf::Color colour;
};

/// Samples of a flown path (t, x, y per step) with velocities from central differences.
std::vector<PathSample> samplesOf(const std::vector<TrackPoint>& path);

/// The paths the last several shots really flew on this level, kept across restarts (as in the original game, where
/// the previous shots stay on screen, dimmed), until the player clears them or plays another level. The play screen
/// owns it and keeps it up to date; the trail layer draws it and the teaching tools measure on it.
class ShotTrails
{
public:
    /// Most paths kept; the oldest goes first.
    static constexpr std::size_t kMaxPaths = 5;

    /// A level started or restarted: paths of the same level are kept, another level's are dropped.
    void onLevelStart(const GameSession& session);
    /// Takes in the session's shots (the last one grows while it flies).
    void update(const GameSession& session);
    /// Forgets every path.
    void clear();

    /// Oldest first.
    const std::deque<MeasuredPath>& paths() const { return m_paths; }
    /// True when the newest kept path is the current session's latest shot (drawn by the play screen itself).
    bool newestIsCurrentShot() const { return m_backIsLive; }

private:
    std::deque<MeasuredPath> m_paths;
    std::string m_levelId;
    std::size_t m_seenShots = 0; ///< shots of the current session already taken in
    bool m_backIsLive = false;
    int m_shotNumber = 0; ///< shots recorded since the last clear
};

} // namespace abalike::app
