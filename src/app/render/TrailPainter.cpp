#include "render/TrailPainter.hpp"

#include "render/Mesh.hpp"
#include "render/Palette.hpp"

#include <algorithm>

namespace abalike::app
{

namespace
{
constexpr double kPuffStepS = 0.05;
constexpr int kLargeEvery = 4;
constexpr float kNewestOpacity = 0.75f;
constexpr float kFadePerShot = 0.14f;
} // namespace

void drawShotTrails(sf::RenderTarget& target, const Camera& camera, const ShotTrails& trails, float uiScale)
{
    const std::deque<MeasuredPath>& paths = trails.paths();
    const std::size_t count = paths.size() - (trails.newestIsCurrentShot() && !paths.empty() ? 1 : 0);
    Mesh mesh;
    for (std::size_t p = 0; p < count; ++p)
    {
        const std::vector<PathSample>& samples = paths[p].samples;
        const float age = static_cast<float>(count - 1 - p);
        const float opacity = std::max(0.2f, kNewestOpacity - kFadePerShot * age);
        const sf::Color puff = faded(palette::kTrailPuff, opacity);
        const sf::Color rim = faded(palette::kTrailRim, opacity);
        int k = 0;
        double nextT = 0.0;
        for (const PathSample& s : samples)
        {
            if (s.t + 1e-9 < nextT)
                continue;
            const bool large = k % kLargeEvery == kLargeEvery - 1;
            // Puffs keep a readable size however far the camera zooms out.
            const float radius =
                std::max((large ? 3.2f : 1.8f) * uiScale, (large ? 0.09f : 0.05f) * camera.pixelsPerMetre());
            const sf::Vector2f at = camera.toScreen({static_cast<float>(s.x), static_cast<float>(s.y)});
            mesh.addCircle(at, radius + 0.8f * uiScale, rim, 10);
            mesh.addCircle(at, radius, puff, 10);
            ++k;
            nextT = static_cast<double>(k) * kPuffStepS;
        }
    }
    mesh.draw(target);
}

} // namespace abalike::app
