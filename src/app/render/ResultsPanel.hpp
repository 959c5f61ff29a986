#pragma once

#include "render/Mesh.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <abalike/game/GameSession.hpp>
#include <string>
#include <vector>

namespace abalike::app
{

/// The end-of-level card: won or lost, where the score came from and the stars earned.
class ResultsPanel
{
public:
    /// font may be null: then only the panel and the stars are drawn.
    explicit ResultsPanel(const sf::Font* font) : m_font(font) {}

    /// Draws the card centred in the window with reserveBelow pixels left free under it (for the menu); returns
    /// where the card is. notes: lines under the total (the endless run's).
    sf::FloatRect draw(sf::RenderTarget& target, sf::Vector2u size, const GameSession& session, float scale,
                       float reserveBelow, const std::vector<std::string>& notes = {});

private:
    const sf::Font* m_font;
    Mesh m_stars;
};

} // namespace abalike::app
