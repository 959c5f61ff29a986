#pragma once

#include <SFML/Graphics/Rect.hpp>
#include <SFML/System/Vector2.hpp>
#include <span>
#include <vector>

namespace abalike::app
{

/// Small geometry on convex polygons given counter-clockwise (y up), used to decorate blocks.
namespace convex
{

/// The polygon shrunk by `distance` on every side; empty when it would vanish.
std::vector<sf::Vector2f> inset(std::span<const sf::Vector2f> polygon, float distance);

/// Clips the segment a-b to the polygon; false when nothing of it is inside.
bool clipSegment(std::span<const sf::Vector2f> polygon, sf::Vector2f& a, sf::Vector2f& b);

/// True when the point is inside or on the polygon.
bool contains(std::span<const sf::Vector2f> polygon, sf::Vector2f point);

/// Axis-aligned bounds of the points.
sf::FloatRect bounds(std::span<const sf::Vector2f> polygon);

/// Area of the polygon (positive for counter-clockwise order).
float signedArea(std::span<const sf::Vector2f> polygon);

/// A regular polygon approximating a circle, counter-clockwise.
std::vector<sf::Vector2f> circle(sf::Vector2f centre, float radius, int segments);

} // namespace convex

} // namespace abalike::app
