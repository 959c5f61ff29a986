// A world mesh cuts curves into the segments their size on the screen needs (Mesh::setPixelSize): each chord within
// 0.2 px of its arc, never more segments than asked for, never fewer than six.
#include "render/Mesh.hpp"

#include <cmath>
#include <gtest/gtest.h>

using namespace abalike::app;

namespace
{
/// Triangles of one circle of the radius (m) at the pixel size (m per pixel; 0: none set), 24 segments asked.
std::size_t circleTriangles(float radiusM, float pixelM)
{
    Mesh mesh;
    mesh.setPixelSize(pixelM);
    mesh.addCircle({0.0f, 0.0f}, radiusM, sf::Color::White, 24);
    return mesh.vertexCount() / 3;
}
} // namespace

TEST(MeshDetail, CurvesGetTheSegmentsTheirSizeOnTheScreenNeeds)
{
    EXPECT_EQ(circleTriangles(0.05f, 0.0f), 24u) << "no pixel size: every segment asked for";
    EXPECT_EQ(circleTriangles(0.05f, 0.05f), 6u) << "1 px across: the fewest";
    // 3 px: 1 - cos(pi/n) <= 0.2/3 needs n >= 8.6, so 10 (even).
    EXPECT_EQ(circleTriangles(0.03f, 0.01f), 10u);
    EXPECT_EQ(circleTriangles(5.0f, 0.01f), 24u) << "500 px: never more than asked for";
    // Each chord stays within 0.2 px of the arc whatever the size.
    for (const float radiusPx : {0.5f, 1.0f, 2.0f, 4.5f, 8.0f, 16.0f, 30.0f, 60.0f})
    {
        const auto n = static_cast<float>(circleTriangles(radiusPx * 0.01f, 0.01f));
        const float sagPx = radiusPx * (1.0f - std::cos(3.14159265f / n));
        EXPECT_TRUE(sagPx <= 0.2f + 1e-4f || n == 24.0f) << radiusPx << " px: " << n << " segments";
    }
}

TEST(MeshDetail, HalfEllipsesKeepAnEvenCountSoTheyCloseOnTheirAxis)
{
    Mesh mesh;
    mesh.setPixelSize(0.01f);
    mesh.addUpperHalfEllipse({0.0f, 0.0f}, 0.045f, 0.02f, sf::Color::White, 32);
    const std::size_t triangles = mesh.vertexCount() / 3;
    // 4.5 px: n = 12 segments for the whole ellipse, half of them drawn; the last vertex lies on the axis.
    EXPECT_EQ(triangles, 6u);
}
