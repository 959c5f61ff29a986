#pragma once

#include "render/Camera.hpp"
#include "render/Mesh.hpp"

namespace abalike::app
{

/// The scenery behind the level: sky gradient, clouds, and the grass-topped ground across the whole view.
class Backdrop
{
public:
    static void paintSky(Mesh& mesh, const Camera& camera, float groundY);
    static void paintGround(Mesh& mesh, const Camera& camera, float groundY);
};

} // namespace abalike::app
