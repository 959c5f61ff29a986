#pragma once

#include <SFML/Graphics/Rect.hpp>
#include <SFML/Graphics/Transform.hpp>
#include <SFML/System/Vector2.hpp>
#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Catalog.hpp>

namespace abalike::app
{

/// Maps world metres (y up) to window pixels (y down) with one uniform scale.
class Camera
{
public:
    /// Frames a level in a window: its home box (levelHomeBox: the slingshot and every body) fitted by fitBox.
    static Camera fitLevel(const LevelDef& level, const Catalog& catalog, sf::Vector2u windowSize);
    /// A view centred on a world point at a scale (pixels per metre), for a window of this size.
    static Camera centredOn(sf::Vector2f centreM, float pixelsPerMetre, sf::Vector2u windowSize);

    /// A view with the given world point (metres) at the window's top-left corner and scale: the editor pans and
    /// zooms with it.
    static Camera fromView(sf::Vector2f worldAtScreenOrigin, float pixelsPerMetre, sf::Vector2u windowSize)
    {
        return Camera(worldAtScreenOrigin, pixelsPerMetre, windowSize);
    }

    sf::Vector2f toScreen(sf::Vector2f world) const { return m_transform.transformPoint(world); }
    sf::Vector2f toWorld(sf::Vector2f screen) const { return m_inverse.transformPoint(screen); }
    /// World metres to pixels, for drawing meshes built in world coordinates.
    const sf::Transform& transform() const { return m_transform; }

    float pixelsPerMetre() const { return m_pixelsPerMetre; }
    float metresPerPixel() const { return 1.0f / m_pixelsPerMetre; }
    /// The part of the world the window shows (left, bottom, width, height in metres).
    sf::FloatRect visibleWorld() const { return m_visible; }
    sf::Vector2u windowSize() const { return m_windowSize; }
    /// The world point at the middle of the window.
    sf::Vector2f centre() const
    {
        return {m_visible.left + 0.5f * m_visible.width, m_visible.top + 0.5f * m_visible.height};
    }

private:
    Camera(sf::Vector2f worldAtScreenOrigin, float pixelsPerMetre, sf::Vector2u windowSize);

    sf::Transform m_transform;
    sf::Transform m_inverse;
    float m_pixelsPerMetre = 1.0f;
    sf::FloatRect m_visible;
    sf::Vector2u m_windowSize;
};

} // namespace abalike::app
