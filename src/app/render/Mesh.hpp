#pragma once

#include <SFML/Graphics/Color.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Transform.hpp>
#include <SFML/Graphics/VertexArray.hpp>
#include <span>
#include <vector>

namespace abalike::app
{

/// A batch of coloured triangles built from simple shapes and drawn in one call. Points are passed through
/// the current local transform as they are added, so shapes can be described in a body's own frame.
class Mesh
{
public:
    Mesh();

    void clear();
    /// Transform applied to every point added from now on (identity by default).
    void setLocalTransform(const sf::Transform& transform) { m_local = transform; }
    void resetLocalTransform() { m_local = sf::Transform::Identity; }

    void addTriangle(sf::Vector2f a, sf::Vector2f b, sf::Vector2f c, sf::Color colour);
    /// A convex polygon, as a triangle fan.
    void addConvex(std::span<const sf::Vector2f> points, sf::Color colour);
    /// An axis-aligned rectangle (in local coordinates) shaded from atMinY along y to atMaxY.
    void addGradientRect(sf::Vector2f min, sf::Vector2f max, sf::Color atMinY, sf::Color atMaxY);
    void addCircle(sf::Vector2f centre, float radius, sf::Color colour, int segments = 24);
    void addEllipse(sf::Vector2f centre, float radiusX, float radiusY, sf::Color colour, int segments = 24);
    /// The half of an ellipse on the +y side of its centre: segments of the whole ellipse, half of them added.
    void addUpperHalfEllipse(sf::Vector2f centre, float radiusX, float radiusY, sf::Color colour, int segments = 24);
    /// A circle outline of the given width, centred on the radius.
    void addRing(sf::Vector2f centre, float radius, float width, sf::Color colour, int segments = 24);
    /// A straight stroke with square ends.
    void addLine(sf::Vector2f a, sf::Vector2f b, float width, sf::Color colour);
    /// A stroke with round ends, for limbs and prongs.
    void addRoundLine(sf::Vector2f a, sf::Vector2f b, float width, sf::Color colour);
    /// Connected strokes through the points.
    void addPolyline(std::span<const sf::Vector2f> points, float width, sf::Color colour);
    /// A five-pointed star.
    void addStar(sf::Vector2f centre, float outerRadius, float innerRadius, sf::Color colour);

    /// blend: sf::BlendNone for opaque fills, which a software rasterizer draws without reading what is under them
    /// and lets it drop whatever was drawn under them before.
    void draw(sf::RenderTarget& target, const sf::Transform& transform = sf::Transform::Identity,
              const sf::BlendMode& blend = sf::BlendAlpha) const;
    /// Vertices added so far (three per triangle).
    std::size_t vertexCount() const { return m_vertices.getVertexCount(); }

private:
    void addVertex(sf::Vector2f point, sf::Color colour);

    sf::VertexArray m_vertices;
    std::vector<sf::Vector2f> m_polyline; ///< addPolyline's kept points, reused between calls
    sf::Transform m_local;
};

} // namespace abalike::app
