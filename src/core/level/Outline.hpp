#pragma once

#include <abalike/level/LevelDef.hpp>
#include <abalike/util/Vec2.hpp>

#include <array>
#include <vector>

namespace abalike
{

/// The designed outline of a body for geometric checks: a convex polygon (counter-clockwise), or a circle.
struct Outline
{
    std::vector<Vec2> vertices; ///< empty for a circle
    Vec2 centre{};
    double radius = 0.0; ///< circles only

    bool isCircle() const { return vertices.empty(); }
    /// Lower and upper corners of the axis-aligned bounding box.
    std::array<Vec2, 2> bounds() const;
};

/// The convex pieces of a block as the world builds it (a hollow box is four walls); none for a shape these checks
/// do not know, which is then not checked.
std::vector<Outline> blockOutlines(const BlockDef& block);
Outline terrainOutline(const TerrainDef& terrain);
/// The convex pieces of a terrain entry as the world builds it: its box, or its polygon split by convexPieces.
std::vector<Outline> terrainOutlines(const TerrainDef& terrain);
Outline circleOutline(double x, double y, double radius);

/// How deep two convex outlines interpenetrate (m), by the separating axis theorem: <= 0 when they are apart or
/// just touch.
double penetration(const Outline& a, const Outline& b);

} // namespace abalike
