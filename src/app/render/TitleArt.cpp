#include "render/TitleArt.hpp"

#include "render/CharacterPainter.hpp"
#include "render/Mesh.hpp"
#include "render/Palette.hpp"

#include <algorithm>
#include <cmath>

namespace abalike::app
{

namespace
{
/// Window pixels (y down) for a painter that draws y up around its origin.
sf::Transform characterAt(sf::Vector2f centre)
{
    sf::Transform transform;
    transform.translate(centre);
    transform.scale(1.0f, -1.0f);
    return transform;
}
} // namespace

void drawTitleArt(sf::RenderTarget& target, float uiScale)
{
    const sf::Vector2f window(target.getSize());
    // Sized by the window's height, and never into the menu's column, whatever the text scale.
    const float unit = std::min(window.y, 0.6f * window.x);
    const sf::Vector2f bird(0.2f * window.x, 0.4f * window.y);
    const float birdR = 0.075f * unit;
    const sf::Vector2f pig(0.85f * window.x, 0.47f * window.y);
    const float pigR = 0.07f * unit;

    Mesh mesh;
    // The arc the bird flew, as the preview draws it: dots from low on the left, rising to the bird.
    const sf::Vector2f start(0.1f * window.x, 0.8f * window.y);
    const sf::Vector2f control(0.1f * window.x, 0.3f * window.y);
    constexpr int kDots = 16;
    for (int i = 0; i < kDots; ++i)
    {
        const float t = static_cast<float>(i) / kDots;
        const sf::Vector2f at = (1.0f - t) * (1.0f - t) * start + 2.0f * t * (1.0f - t) * control + t * t * bird;
        if (std::hypot(at.x - bird.x, at.y - bird.y) < 1.3f * birdR)
            break;
        mesh.addCircle(at, 4.0f * uiScale, palette::kPreviewOutline, 10);
        mesh.addCircle(at, 2.8f * uiScale, palette::kPreviewDot, 10);
    }

    // A tilted bird, nose up along the arc.
    sf::Transform birdTransform = characterAt(bird);
    birdTransform.rotate(-20.0f);
    mesh.setLocalTransform(birdTransform);
    CharacterPainter::paintBird(mesh, Catalog::builtin().birds().front(), birdR, 1.0f); // the first bird: red

    // The helmet pig it is after, grinning.
    mesh.setLocalTransform(characterAt(pig));
    CharacterPainter::paintPig(mesh, pigR, true, 1.0f, 1.0f);
    mesh.resetLocalTransform();
    mesh.draw(target);
}

} // namespace abalike::app
