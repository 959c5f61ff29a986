#pragma once

#include "edit/ConvexShape.hpp"

#include <abalike/edit/SceneObject.hpp>
#include <abalike/edit/Snapping.hpp>
#include <abalike/world/Catalog.hpp>

#include <array>
#include <string>

namespace abalike
{

// Small helpers the editing model's files share.

/// Heights and edges closer than this are the same: parts' coordinates carry float noise, and a last-bit difference
/// must not decide a storey line, an occupied cell or a side.
inline constexpr double kSameEdgeM = 1e-6;

/// A terrain polygon's box (x, y, w, h) made its points' bounding box again after they changed.
void fitPolygonBounds(TerrainDef& terrain);

/// True when (x, y) lies inside a simple polygon, convex or not, either winding (even-odd rule).
bool polygonContains(const std::vector<Vec2>& points, double x, double y);

/// Turns a terrain polygon's points about its bounding box's centre; its box follows (a polygon has no angle).
void rotatePolygon(TerrainDef& terrain, double deltaDeg);

/// A coordinate cleaned to the micrometre and kept inside the world.
double clampCoordinate(double value);

/// Angles are kept in (-180, 180] so that turning never leaves the format's -360..360.
double normaliseAngle(double degrees);

/// "3 objects", "1 object".
std::string plural(std::size_t count, const char* what);

/// "Move 3 objects": an undo step's label.
std::string labelFor(const char* verb, std::size_t count);

/// Bounds of an object for rectangle selection: its shape's, or the slingshot's point.
std::array<Vec2, 2> objectBounds(const ObjectDef& def, const Catalog& catalog);

} // namespace abalike
