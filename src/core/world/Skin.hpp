#pragma once

#include <box2d/box2d.h>
#include <vector>

namespace abalike
{

// Box2D keeps polygons and edges apart by a skin (b2_polygonRadius = 1 cm) and lets resting contacts settle
// b2_linearSlop (5 mm) into it, so shapes built at their drawn size rest 1.5 cm apart per contact and stacks
// grow. These adjustments make every resting contact land exactly on the designed surfaces:
//   polygon-polygon: cores rest 2r - slop = 15 mm apart, so each polygon is inset by r - slop/2 = 7.5 mm;
//   circle-polygon: a circle (no skin) rests radius + r - slop from the core, so circles grow by slop/2;
//   the ground edge (skin r) sits 7.5 mm below the ground line.
// Box2D finds polygon contacts by separating axes (b2CollidePolygons), which treats the skin around a corner as
// square: two blocks that only meet corner to corner (diagonal neighbours in a wall of aligned bricks) get a
// contact whose normal flips between horizontal and vertical, although their rounded skins are 21 mm apart.
// Cutting each core corner by kCornerChamfer adds a diagonal axis along which they are 25 mm apart (more than
// the 20 mm of two skins), so such pairs never touch; face-to-face contacts are unchanged.

/// How far polygon shapes are inset from their designed outline.
inline constexpr float kPolygonInset = b2_polygonRadius - 0.5f * b2_linearSlop;
/// How much circle shapes are larger than their designed radius.
inline constexpr float kCircleGrowth = 0.5f * b2_linearSlop;

/// Radius of the Box2D circle for a designed radius.
inline float physicsCircleRadius(double designedRadius)
{
    return static_cast<float>(designedRadius) + kCircleGrowth;
}

/// How far each corner of a polygon core is cut back along both of its edges (3 mm: above Box2D's 2.5 mm vertex
/// welding distance, invisible at any zoom the game uses).
inline constexpr float kCornerChamfer = 0.003f;

/// A convex polygon (counter-clockwise) moved inwards by kPolygonInset on every edge.
std::vector<b2Vec2> insetPolygon(const std::vector<b2Vec2>& outline);

/// The polygon with the vertices marked in cut (all when empty) replaced by two points `chamfer` metres along
/// their edges. At most 4 vertices in (Box2D polygons have at most 8).
std::vector<b2Vec2> chamferCorners(const std::vector<b2Vec2>& polygon, float chamfer,
                                   const std::vector<bool>& cut = {});

} // namespace abalike
