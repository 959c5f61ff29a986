#pragma once

#include <abalike/util/Vec2.hpp>
#include <array>
#include <optional>
#include <vector>

namespace abalike
{

/// Twice the signed area of a polygon: > 0 counter-clockwise.
double twiceSignedArea(const std::vector<Vec2>& polygon);

/// Two edges of a polygon that cross or touch other than at a shared corner: edge i runs from point i to point i+1.
struct EdgeCrossing
{
    std::size_t first = 0;
    std::size_t second = 0;
};

/// The first pair of non-adjacent edges that cross or touch (or adjacent ones that fold back on each other); none
/// when the polygon is simple.
std::optional<EdgeCrossing> firstCrossing(const std::vector<Vec2>& polygon);

/// Splits a simple polygon (either winding, convex or not) into convex pieces of at most maxVertices corners each,
/// counter-clockwise: ear clipping into triangles, then neighbours merged while the union stays convex
/// (Hertel-Mehlhorn), so a convex polygon of up to maxVertices corners comes back whole. Box2D collides only convex
/// polygons of at most 8 corners.
std::vector<std::vector<Vec2>> convexPieces(std::vector<Vec2> polygon, std::size_t maxVertices = 8);

} // namespace abalike
