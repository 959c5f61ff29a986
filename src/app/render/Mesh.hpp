#pragma once

#include <SFML/Graphics/Color.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Transform.hpp>
#include <SFML/Graphics/Vertex.hpp>
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
    void setLocalTransform(const sf::Transform& transform);
    void resetLocalTransform() { setLocalTransform(sf::Transform::Identity); }
    /// The size of a screen pixel in the units points are given in (metres per pixel for a world mesh). With it,
    /// curves get only the segments their size on the screen needs (never more than asked for): a pig's 2-pixel
    /// nostril is not cut into 24 triangles. 0, the default, keeps every segment asked for. Kept by clear().
    void setPixelSize(float unitsPerPixel) { m_pixelSize = unitsPerPixel; }

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
    std::size_t vertexCount() const { return m_vertices.size(); }

private:
    void addVertex(sf::Vector2f point, sf::Color colour);
    /// Segments for a curve of this radius: as asked, or fewer where each chord stays within kChordTolerancePx of
    /// the arc on the screen (see setPixelSize); always even, so that half an ellipse closes on its axis.
    int segmentsFor(float radius, int asked) const;

    /// A plain vector rather than sf::VertexArray: a frame adds tens of thousands of vertices, and appending through
    /// SFML's library calls (and sf::Transform::transformPoint's) took a tenth of the frame's drawing.
    std::vector<sf::Vertex> m_vertices;
    std::vector<sf::Vector2f> m_polyline; ///< addPolyline's kept points, reused between calls
    /// The local transform's 2D part: x' = a x + b y + c, y' = d x + e y + f.
    float m_a = 1.0f, m_b = 0.0f, m_c = 0.0f, m_d = 0.0f, m_e = 1.0f, m_f = 0.0f;
    float m_pixelSize = 0.0f;
};

} // namespace abalike::app
