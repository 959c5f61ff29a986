#include "render/Mesh.hpp"

#include "render/ScreenRegions.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace abalike::app
{

namespace
{
constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
/// How far (in pixels) a chord of a curve may fall inside its arc: under a fifth of a pixel, the few edge pixels whose
/// centres it moves past change colour and nothing else does.
constexpr float kChordTolerancePx = 0.2f;
constexpr int kFewestSegments = 6;

sf::Vector2f unitNormal(sf::Vector2f a, sf::Vector2f b)
{
    const sf::Vector2f d = b - a;
    const float length = std::sqrt(d.x * d.x + d.y * d.y);
    if (length <= 0.0f)
        return {0.0f, 0.0f};
    return {-d.y / length, d.x / length};
}
} // namespace

Mesh::Mesh() = default;

void Mesh::clear()
{
    m_vertices.clear();
    resetLocalTransform();
}

void Mesh::setLocalTransform(const sf::Transform& transform)
{
    // sf::Transform keeps a 4x4 column-major matrix; a 2D affine transform uses six of its entries.
    const float* m = transform.getMatrix();
    m_a = m[0];
    m_b = m[4];
    m_c = m[12];
    m_d = m[1];
    m_e = m[5];
    m_f = m[13];
}

void Mesh::addVertex(sf::Vector2f point, sf::Color colour)
{
    // The same arithmetic as sf::Transform::transformPoint, so the vertices are bit for bit what they were.
    m_vertices.emplace_back(sf::Vector2f(m_a * point.x + m_b * point.y + m_c, m_d * point.x + m_e * point.y + m_f),
                            colour);
}

void Mesh::addTriangle(sf::Vector2f a, sf::Vector2f b, sf::Vector2f c, sf::Color colour)
{
    addVertex(a, colour);
    addVertex(b, colour);
    addVertex(c, colour);
}

void Mesh::addConvex(std::span<const sf::Vector2f> points, sf::Color colour)
{
    for (std::size_t i = 1; i + 1 < points.size(); ++i)
        addTriangle(points[0], points[i], points[i + 1], colour);
}

void Mesh::addGradientRect(sf::Vector2f min, sf::Vector2f max, sf::Color atMinY, sf::Color atMaxY)
{
    addVertex(min, atMinY);
    addVertex({max.x, min.y}, atMinY);
    addVertex(max, atMaxY);
    addVertex(min, atMinY);
    addVertex(max, atMaxY);
    addVertex({min.x, max.y}, atMaxY);
}

int Mesh::segmentsFor(float radius, int asked) const
{
    if (m_pixelSize <= 0.0f || asked <= kFewestSegments)
        return asked;
    const float radiusPx = std::abs(radius) / m_pixelSize;
    // A chord of angle 2*pi/n falls r * (1 - cos(pi/n)) inside the arc.
    if (radiusPx <= kChordTolerancePx)
        return kFewestSegments;
    const float cosine = 1.0f - kChordTolerancePx / radiusPx;
    const int needed = static_cast<int>(std::ceil(std::numbers::pi_v<float> / std::acos(cosine)));
    const int even = needed + needed % 2;
    return std::clamp(even, kFewestSegments, asked);
}

void Mesh::addCircle(sf::Vector2f centre, float radius, sf::Color colour, int segments)
{
    addEllipse(centre, radius, radius, colour, segments);
}

void Mesh::addEllipse(sf::Vector2f centre, float radiusX, float radiusY, sf::Color colour, int segments)
{
    segments = segmentsFor(std::max(std::abs(radiusX), std::abs(radiusY)), segments);
    sf::Vector2f previous = centre + sf::Vector2f(radiusX, 0.0f);
    for (int i = 1; i <= segments; ++i)
    {
        const float angle = kTwoPi * static_cast<float>(i) / static_cast<float>(segments);
        const sf::Vector2f next = centre + sf::Vector2f(radiusX * std::cos(angle), radiusY * std::sin(angle));
        addTriangle(centre, previous, next, colour);
        previous = next;
    }
}

void Mesh::addUpperHalfEllipse(sf::Vector2f centre, float radiusX, float radiusY, sf::Color colour, int segments)
{
    segments = segmentsFor(std::max(std::abs(radiusX), std::abs(radiusY)), segments);
    sf::Vector2f previous = centre + sf::Vector2f(radiusX, 0.0f);
    for (int i = 1; 2 * i <= segments; ++i)
    {
        const float angle = kTwoPi * static_cast<float>(i) / static_cast<float>(segments);
        const sf::Vector2f next = centre + sf::Vector2f(radiusX * std::cos(angle), radiusY * std::sin(angle));
        addTriangle(centre, previous, next, colour);
        previous = next;
    }
}

void Mesh::addRing(sf::Vector2f centre, float radius, float width, sf::Color colour, int segments)
{
    const float inner = radius - 0.5f * width;
    const float outer = radius + 0.5f * width;
    segments = segmentsFor(outer, segments);
    for (int i = 0; i < segments; ++i)
    {
        const float a0 = kTwoPi * static_cast<float>(i) / static_cast<float>(segments);
        const float a1 = kTwoPi * static_cast<float>(i + 1) / static_cast<float>(segments);
        const sf::Vector2f d0(std::cos(a0), std::sin(a0));
        const sf::Vector2f d1(std::cos(a1), std::sin(a1));
        addTriangle(centre + d0 * inner, centre + d0 * outer, centre + d1 * outer, colour);
        addTriangle(centre + d0 * inner, centre + d1 * outer, centre + d1 * inner, colour);
    }
}

void Mesh::addLine(sf::Vector2f a, sf::Vector2f b, float width, sf::Color colour)
{
    const sf::Vector2f n = unitNormal(a, b) * (0.5f * width);
    addTriangle(a + n, b + n, b - n, colour);
    addTriangle(a + n, b - n, a - n, colour);
}

void Mesh::addRoundLine(sf::Vector2f a, sf::Vector2f b, float width, sf::Color colour)
{
    addLine(a, b, width, colour);
    addCircle(a, 0.5f * width, colour, 12);
    addCircle(b, 0.5f * width, colour, 12);
}

void Mesh::addPolyline(std::span<const sf::Vector2f> points, float width, sf::Color colour)
{
    // Points closer than a fifth of the width to the last one kept add nothing the stroke shows, but a path recorded
    // once a step piles hundreds of them where a bird rests, each a translucent joint over the same pixels.
    const float minGap = 0.2f * width;
    m_polyline.clear();
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        const bool last = i + 1 == points.size();
        if (m_polyline.empty() || last)
            m_polyline.push_back(points[i]);
        else if (const sf::Vector2f d = points[i] - m_polyline.back(); d.x * d.x + d.y * d.y >= minGap * minGap)
            m_polyline.push_back(points[i]);
    }
    for (std::size_t i = 1; i < m_polyline.size(); ++i)
        addLine(m_polyline[i - 1], m_polyline[i], width, colour);
    // Small joints fill the notches between segments where the line bends.
    for (std::size_t i = 1; i + 1 < m_polyline.size(); ++i)
        addCircle(m_polyline[i], 0.5f * width, colour, 8);
}

void Mesh::addStar(sf::Vector2f centre, float outerRadius, float innerRadius, sf::Color colour)
{
    constexpr int kPoints = 5;
    for (int i = 0; i < 2 * kPoints; ++i)
    {
        // Start at the top point (y grows downwards on screen, so "up" is -y there; callers flip as needed).
        const float a0 = -std::numbers::pi_v<float> / 2.0f + kTwoPi * static_cast<float>(i) / (2.0f * kPoints);
        const float a1 = -std::numbers::pi_v<float> / 2.0f + kTwoPi * static_cast<float>(i + 1) / (2.0f * kPoints);
        const float r0 = (i % 2 == 0) ? outerRadius : innerRadius;
        const float r1 = (i % 2 == 0) ? innerRadius : outerRadius;
        addTriangle(centre, centre + sf::Vector2f(r0 * std::cos(a0), r0 * std::sin(a0)),
                    centre + sf::Vector2f(r1 * std::cos(a1), r1 * std::sin(a1)), colour);
    }
}

void Mesh::draw(sf::RenderTarget& target, const sf::Transform& transform, const sf::BlendMode& blend) const
{
    if (m_vertices.empty() || !drawingPixels())
        return;
    sf::RenderStates states;
    states.transform = transform;
    states.blendMode = blend;
    target.draw(m_vertices.data(), m_vertices.size(), sf::Triangles, states);
}

} // namespace abalike::app
