#pragma once

#include "render/Mesh.hpp"

#include <optional>

namespace abalike::app
{

/// Where the slingshot stands and what it holds, in world metres.
struct SlingshotPose
{
    sf::Vector2f base;                      ///< foot of the trunk on the ground
    sf::Vector2f pouch;                     ///< where the bird leaves the slingshot
    std::optional<sf::Vector2f> loadedBird; ///< centre of the bird in the pouch (pulled back while aiming)
    float birdRadius = 0.25f;
};

/// Draws the wooden Y and its rubber bands in two layers, so the loaded bird sits between the prongs:
/// paintBack, then the bird, then paintFront.
class SlingshotPainter
{
public:
    static void paintBack(Mesh& mesh, const SlingshotPose& pose, float pixelM);
    static void paintFront(Mesh& mesh, const SlingshotPose& pose, float pixelM);
};

} // namespace abalike::app
