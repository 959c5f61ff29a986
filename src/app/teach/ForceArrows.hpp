#pragma once

#include "render/Camera.hpp"
#include "teach/BirdReadout.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

namespace abalike::app
{

/// Arrows on the flying bird -- velocity (with components vx and vy if asked), the velocity relative to the air when
/// there is wind, acceleration and each force on its own, each named at its tip -- drawn in the world.
void drawForceArrows(sf::RenderTarget& target, const sf::Font& font, const Camera& camera, const BirdReadout& bird,
                     bool components, unsigned labelSize, float scale);

/// The legend of those arrows with their values in SI units; returns its bounds. Where it has no room
/// (panelHasRoom), a one-line summary (drawPanelSummary) or nothing.
sf::FloatRect drawForceLegend(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topRight,
                              const BirdReadout& bird, bool hasDrag, bool hasWind, bool components, unsigned titleSize,
                              unsigned rowSize, float scale);

/// Bars of kinetic, potential and total energy and of the energy drag has taken, against the launch energy;
/// `at` is the panel's top-right corner. Returns its bounds; where it has no room, a one-line summary or nothing.
sf::FloatRect drawEnergyBars(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topRight,
                             const FlightEnergy& energy, bool atContact, unsigned titleSize, unsigned rowSize,
                             float scale);

} // namespace abalike::app
