#include "render/Backdrop.hpp"

#include "render/DetailRandom.hpp"
#include "render/Palette.hpp"

#include <algorithm>
#include <cmath>

namespace abalike::app
{

namespace
{
/// A gradient fill into the opaque batch when both its colours are opaque, else into the blended one.
void addFill(Mesh& base, Mesh& detail, sf::Vector2f min, sf::Vector2f max, sf::Color atMinY, sf::Color atMaxY)
{
    Mesh& mesh = atMinY.a == 255 && atMaxY.a == 255 ? base : detail;
    mesh.addGradientRect(min, max, atMinY, atMaxY);
}
} // namespace

void Backdrop::paint(Mesh& base, Mesh& detail, const Camera& camera, float groundY, const Scenery& scenery)
{
    paintSky(base, detail, camera, groundY, scenery);
    paintGround(base, detail, camera, groundY, scenery);
}

void Backdrop::paintSky(Mesh& base, Mesh& mesh, const Camera& camera, float groundY, const Scenery& scenery)
{
    const sf::FloatRect view = camera.visibleWorld();
    const float top = view.top + view.height;
    addFill(base, mesh, {view.left, groundY}, {view.left + view.width, top}, scenery.skyBottom, scenery.skyTop);

    DetailRandom random(7);
    const float skyHeight = top - groundY;
    if (scenery.stars)
    {
        // An airless sky: fixed stars across the view, a pixel or two each.
        const float pixel = camera.metresPerPixel();
        for (int i = 0; i < 90; ++i)
        {
            const sf::Vector2f at(random.range(view.left, view.left + view.width),
                                  groundY + skyHeight * random.range(0.15f, 1.0f));
            mesh.addCircle(at, pixel * random.range(0.7f, 1.6f), sf::Color(235, 235, 245, 210), 6);
        }
    }
    if (scenery.bands)
    {
        // Cloud belts: darker and lighter stripes across the sky, fixed in the sky like the gradient.
        const sf::Color belts[] = {sf::Color(150, 96, 64, 90), sf::Color(250, 236, 210, 80),
                                   sf::Color(170, 110, 72, 80), sf::Color(140, 90, 60, 70)};
        const float heights[] = {0.82f, 0.68f, 0.55f, 0.36f};
        for (int i = 0; i < 4; ++i)
        {
            const float y = groundY + skyHeight * heights[i];
            mesh.addGradientRect({view.left, y}, {view.left + view.width, y + skyHeight * 0.06f}, belts[i], belts[i]);
        }
    }
    // Clouds at fixed places across the view, each a cluster of puffs (none without air).
    constexpr int kClouds = 5;
    for (int i = 0; i < kClouds && scenery.cloud.a > 0; ++i)
    {
        const float x = view.left + view.width * (static_cast<float>(i) + random.range(0.2f, 0.8f)) / kClouds;
        const float y = groundY + skyHeight * random.range(0.55f, 0.85f);
        const float size = skyHeight * random.range(0.035f, 0.055f);
        mesh.addEllipse({x, y}, 2.2f * size, 0.9f * size, scenery.cloud, 24);
        mesh.addCircle({x - 0.8f * size, y + 0.4f * size}, 0.9f * size, scenery.cloud, 20);
        mesh.addCircle({x + 0.5f * size, y + 0.6f * size}, 1.1f * size, scenery.cloud, 20);
    }
    paintHills(mesh, view, groundY, 0.25f, 26.0f, scenery.hillFar, 3);
    paintHills(mesh, view, groundY, 0.5f, 17.0f, scenery.hillNear, 5);
}

void Backdrop::paintHills(Mesh& mesh, const sf::FloatRect& view, float groundY, float depth, float periodM,
                          sf::Color colour, std::uint64_t seed)
{
    // Parallax: the row is laid out in its own coordinate u = x - left * (1 - depth), so when the camera moves by
    // d the hills move by only depth * d in the world shown, and so cross the window slower than the level: far
    // away. Each hill is seeded by its index, so a hill keeps its shape as it scrolls.
    const float right = view.left + view.width;
    const float offset = view.left * (1.0f - depth);
    const auto first = static_cast<long long>(std::floor((view.left - offset) / periodM)) - 2;
    for (long long k = first;; ++k)
    {
        DetailRandom random(seed * 1000003ull + static_cast<std::uint64_t>(k + (1ll << 40)));
        const float x = offset + (static_cast<float>(k) + random.range(0.0f, 0.6f)) * periodM;
        const float radius = periodM * random.range(0.7f, 1.1f);
        if (x - radius > right)
            break;
        // Low, so the structure, the preview dots and the labels stand out against the sky, not against a hill. Only
        // the half above the ground line: the ground is drawn first (opaque) and would not hide the lower half.
        const float height = periodM * random.range(0.07f, 0.13f) * (depth < 0.4f ? 1.3f : 1.0f);
        mesh.addUpperHalfEllipse({x, groundY}, radius, height, colour, 32);
    }
}

void Backdrop::paintGround(Mesh& base, Mesh& mesh, const Camera& camera, float groundY, const Scenery& scenery)
{
    const sf::FloatRect view = camera.visibleWorld();
    const float left = view.left;
    const float right = view.left + view.width;
    const float bottom = std::min(view.top, groundY - 1.0f);
    const float pixelM = camera.metresPerPixel();
    const float grass = std::max(0.3f, 7.0f * pixelM);

    addFill(base, mesh, {left, bottom}, {right, groundY}, scenery.groundDark, scenery.ground);
    // Pebbles in the earth.
    DetailRandom random(11);
    const int pebbles = std::clamp(static_cast<int>(view.width * 1.5f), 10, 200);
    for (int i = 0; i < pebbles; ++i)
    {
        // Wholly under the grass band, which is drawn before them.
        const float radiusY = std::max(0.05f, 1.4f * pixelM);
        // y is drawn before x: the pebbles keep the places they have always had.
        const float y = std::min(random.range(bottom, groundY - grass), groundY - grass - radiusY);
        const sf::Vector2f p(random.range(left, right), y);
        mesh.addEllipse(p, std::max(0.08f, 2.0f * pixelM), radiusY, scenery.groundDark, 8);
    }
    addFill(base, mesh, {left, groundY - grass}, {right, groundY}, scenery.surfaceDark, scenery.surface);
    if (!scenery.blades)
        return;
    // Blades along the top edge.
    const float blade = std::max(0.12f, 4.0f * pixelM);
    for (float x = left; x < right; x += blade * 0.9f)
        mesh.addTriangle({x, groundY - 0.01f}, {x + 0.5f * blade, groundY + 0.6f * blade}, {x + blade, groundY - 0.01f},
                         scenery.surface);
}

} // namespace abalike::app
