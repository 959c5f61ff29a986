#pragma once

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <abalike/world/GameWorld.hpp>

namespace abalike::app
{

/// The first impact in numbers: momentum and kinetic energy of the bird and of what it hit, just before and just
/// after, the impulse they exchanged, the damage against what the body could still take ("X of the Y N·s") and
/// the coefficient of restitution where nothing broke. topRight: where its top right corner goes (it is
/// as wide as its numbers need; a panel wider than that much room starts at the window's left edge). Returns its
/// bounds; where it has no room (panelHasRoom), a one-line summary (drawPanelSummary) or nothing. School wording gives
/// spin in turns per second and calls restitution "bounciness"; university wording, rad/s and restitution.
sf::FloatRect drawImpactPanel(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topRight,
                              const FirstImpact& impact, bool university, unsigned titleSize, unsigned rowSize,
                              float scale);

} // namespace abalike::app
