#pragma once

#include "render/AimReadout.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/Rect.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

namespace abalike::app
{

/// The band's force against its pull while aiming: the straight line F = k x up to the full pull, the current pull
/// marked on it, and the triangle under it shaded: its area, 1/2 F x, is the energy the bird will leave with.
class BandGraph
{
public:
    /// Size it takes at these text sizes.
    static sf::Vector2f measure(const sf::Font& font, unsigned titleSize, unsigned rowSize, float scale);
    /// Draws it with its top-right corner at `topRight`; returns its bounds.
    static sf::FloatRect draw(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topRight,
                              const AimReadout& aim, unsigned titleSize, unsigned rowSize, float scale);
};

} // namespace abalike::app
