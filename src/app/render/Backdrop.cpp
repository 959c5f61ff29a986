#include "render/Backdrop.hpp"

#include "render/DetailRandom.hpp"
#include "render/Palette.hpp"

#include <algorithm>
#include <cmath>

namespace abalike::app
{

void Backdrop::paintSky(Mesh& mesh, const Camera& camera, float groundY)
{
    const sf::FloatRect view = camera.visibleWorld();
    const float top = view.top + view.height;
    mesh.addGradientRect({view.left, groundY}, {view.left + view.width, top}, palette::kSkyBottom, palette::kSkyTop);

    // Clouds at fixed places across the view, each a cluster of puffs.
    DetailRandom random(7);
    const float skyHeight = top - groundY;
    constexpr int kClouds = 5;
    for (int i = 0; i < kClouds; ++i)
    {
        const float x = view.left + view.width * (static_cast<float>(i) + random.range(0.2f, 0.8f)) / kClouds;
        const float y = groundY + skyHeight * random.range(0.55f, 0.85f);
        const float size = skyHeight * random.range(0.035f, 0.055f);
        mesh.addEllipse({x, y}, 2.2f * size, 0.9f * size, palette::kCloud, 24);
        mesh.addCircle({x - 0.8f * size, y + 0.4f * size}, 0.9f * size, palette::kCloud, 20);
        mesh.addCircle({x + 0.5f * size, y + 0.6f * size}, 1.1f * size, palette::kCloud, 20);
    }
}

void Backdrop::paintGround(Mesh& mesh, const Camera& camera, float groundY)
{
    const sf::FloatRect view = camera.visibleWorld();
    const float left = view.left;
    const float right = view.left + view.width;
    const float bottom = std::min(view.top, groundY - 1.0f);
    const float pixelM = camera.metresPerPixel();
    const float grass = std::max(0.3f, 7.0f * pixelM);

    mesh.addGradientRect({left, bottom}, {right, groundY}, palette::kEarthDark, palette::kEarth);
    // Pebbles in the earth.
    DetailRandom random(11);
    const int pebbles = std::clamp(static_cast<int>(view.width * 1.5f), 10, 200);
    for (int i = 0; i < pebbles; ++i)
    {
        const sf::Vector2f p(random.range(left, right), random.range(bottom, groundY - grass));
        mesh.addEllipse(p, std::max(0.08f, 2.0f * pixelM), std::max(0.05f, 1.4f * pixelM), palette::kEarthDark, 8);
    }
    mesh.addGradientRect({left, groundY - grass}, {right, groundY}, palette::kGrassDark, palette::kGrass);
    // Blades along the top edge.
    const float blade = std::max(0.12f, 4.0f * pixelM);
    for (float x = left; x < right; x += blade * 0.9f)
        mesh.addTriangle({x, groundY - 0.01f}, {x + 0.5f * blade, groundY + 0.6f * blade}, {x + blade, groundY - 0.01f},
                         palette::kGrass);
}

} // namespace abalike::app
