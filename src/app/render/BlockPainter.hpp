#pragma once

#include "render/Mesh.hpp"

#include <abalike/world/Looks.hpp>

#include <cstdint>
#include <span>
#include <string_view>

namespace abalike::app
{

/// How one block should look.
struct BlockLook
{
    const MaterialLook* material = nullptr; ///< the block's material's look (the catalog's)
    float healthFraction = 1.0f;            ///< health / maxHealth: cracks below 0.66, more and darker below 0.33
    std::uint64_t seed = 0;                 ///< keeps grain, speckles and cracks the same from frame to frame
    float pixelM = 0.03f;                   ///< one screen pixel in metres, so strokes stay visible at any zoom
};

/// Draws blocks in their material: wood with grain, translucent ice with a glint, speckled stone; cracks
/// show damage. Shapes are given in the body's frame; the mesh's local transform places them.
class BlockPainter
{
public:
    /// A convex polygon, counter-clockwise, as Box2D stores it.
    static void paintPolygon(Mesh& mesh, std::span<const sf::Vector2f> polygon, const BlockLook& look);
    /// A round block.
    static void paintDisc(Mesh& mesh, sf::Vector2f centre, float radius, const BlockLook& look);
};

} // namespace abalike::app
