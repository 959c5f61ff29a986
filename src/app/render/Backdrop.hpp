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
    /// Paints the backdrop in two batches. `base` gets the opaque fills that cover the whole view (the sky and
    /// ground gradients and the grass band) and is meant to be drawn without blending: a software rasterizer then
    /// neither reads the pixels under them nor fills what was drawn under them before. `detail` gets everything
    /// drawn over them (and any fill of a world whose colours are see-through).
    static void paint(Mesh& base, Mesh& detail, const Camera& camera, float groundY, const Scenery& scenery);

private:
    static void paintSky(Mesh& base, Mesh& detail, const Camera& camera, float groundY, const Scenery& scenery);
    static void paintGround(Mesh& base, Mesh& detail, const Camera& camera, float groundY, const Scenery& scenery);
    /// A row of rounded hills standing on the ground line that scrolls at `depth` (0: fixed to the window, 1: with
    /// the level) as the camera pans: the parallax that tells the player the camera moved.
    static void paintHills(Mesh& mesh, const sf::FloatRect& view, float groundY, float depth, float periodM,
                           sf::Color colour, std::uint64_t seed);
};

} // namespace abalike::app
