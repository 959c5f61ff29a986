#pragma once

#include "render/Scenery.hpp"

#include "render/Camera.hpp"
#include "render/Mesh.hpp"

#include <cstdint>

namespace abalike::app
{

/// The scenery behind the level: sky gradient, clouds, two rows of hills in parallax, and the grass-topped ground
/// across the whole view.
class Backdrop
{
public:
    static void paintSky(Mesh& mesh, const Camera& camera, float groundY, const Scenery& scenery);
    static void paintGround(Mesh& mesh, const Camera& camera, float groundY, const Scenery& scenery);

private:
    /// A row of rounded hills standing on the ground line that scrolls at `depth` (0: fixed to the window, 1: with
    /// the level) as the camera pans: the parallax that tells the player the camera moved.
    static void paintHills(Mesh& mesh, const sf::FloatRect& view, float groundY, float depth, float periodM,
                           sf::Color colour, std::uint64_t seed);
};

} // namespace abalike::app
