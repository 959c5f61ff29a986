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

/// How far polygon shapes are inset from their designed outline.
inline constexpr float kPolygonInset = b2_polygonRadius - 0.5f * b2_linearSlop;
/// How much circle shapes are larger than their designed radius.
inline constexpr float kCircleGrowth = 0.5f * b2_linearSlop;

/// Radius of the Box2D circle for a designed radius.
inline float physicsCircleRadius(double designedRadius)
{
    return static_cast<float>(designedRadius) + kCircleGrowth;
}

/// A convex polygon (counter-clockwise) moved inwards by kPolygonInset on every edge.
std::vector<b2Vec2> insetPolygon(const std::vector<b2Vec2>& outline);

} // namespace abalike
