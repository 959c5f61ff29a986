#pragma once

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <abalike/game/GameSession.hpp>

namespace abalike::app
{

/// "Why the preview and the world can differ", with the live numbers of the current shot: what the preview
/// integrates, where Box2D takes over, how far apart they ended. Returns its bounds; where it has
/// no room (panelHasRoom), a one-line summary (drawPanelSummary) or nothing.
sf::FloatRect drawWhyPanel(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topLeft,
                           const GameSession& session, const PredictedFlight* preview, bool university,
                           unsigned titleSize, unsigned rowSize, float scale);

} // namespace abalike::app
