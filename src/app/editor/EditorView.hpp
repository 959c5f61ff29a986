#pragma once

#include "render/Camera.hpp"

#include <SFML/Graphics/Rect.hpp>
#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Catalog.hpp>

namespace abalike::app
{

/// The editor's view of the scene: pan and zoom about the pointer, and fitting the whole scene into the part of the
/// window the panels leave free.
class EditorView
{
public:
    /// Frames the slingshot, every object and the ground inside `area` (window pixels).
    void fit(const LevelDef& level, const Catalog& catalog, sf::FloatRect area, sf::Vector2u windowSize);
    /// Moves the view by a drag of `pixels`.
    void pan(sf::Vector2f pixels);
    /// Zooms by `factor` keeping the world point under `pixel` where it is.
    void zoomAt(sf::Vector2f pixel, float factor);

    Camera camera(sf::Vector2u windowSize) const;
    sf::Vector2f toWorld(sf::Vector2f pixel) const;
    float pixelsPerMetre() const { return m_pixelsPerMetre; }

private:
    sf::Vector2f m_origin{-5.0f, 12.0f}; ///< the world point at the window's top-left corner (m)
    float m_pixelsPerMetre = 40.0f;
};

} // namespace abalike::app
