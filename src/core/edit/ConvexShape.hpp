#pragma once

#include "level/Outline.hpp"

#include <abalike/edit/SceneObject.hpp>

#include <array>
#include <optional>
#include <vector>

namespace abalike
{

class Catalog;

/// A convex polygon, counter-clockwise, for the editor's geometry: picking and snapping.
using ConvexShape = std::vector<Vec2>;

/// Circles become polygons of this many sides, with vertices exactly at the bottom, top, left and right, so a
/// circle rests exactly on a level surface (and within 0.12 % of its radius on a slope).
inline constexpr int kCircleSides = 64;

/// The convex outline of a block, pig or terrain piece (a hollow box's outer frame); empty for the slingshot, which
/// is not a body, and for an unknown pig type.
ConvexShape objectShape(const ObjectDef& def, const Catalog& catalog);

/// Lower and upper corners of a shape's bounding box.
std::array<Vec2, 2> shapeBounds(const ConvexShape& shape);

/// True if the point is inside the shape or on its edge.
bool shapeContains(const ConvexShape& shape, const Vec2& point);

/// The translations t along the unit direction u for which `moving`, moved by t u, overlaps `fixed`: [t0, t1]. At t0
/// the two just touch with moving behind fixed (t0 > 0: it has that far to go; t0 < 0: it is already in, that far).
/// None when moving along u never overlaps fixed by more than a graze (the two only slide past each other).
std::optional<std::array<double, 2>> contactInterval(const ConvexShape& moving, const ConvexShape& fixed,
                                                     const Vec2& u);

} // namespace abalike
