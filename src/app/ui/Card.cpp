#include "ui/Card.hpp"

#include "render/Palette.hpp"

#include <SFML/Graphics/RectangleShape.hpp>

namespace abalike::app
{

void drawScrim(sf::RenderTarget& target)
{
    const sf::Vector2f size(target.getSize());
    sf::RectangleShape shade(size);
    shade.setFillColor(palette::kScrim);
    target.draw(shade);
}

void drawCard(sf::RenderTarget& target, sf::FloatRect rect, float scale, sf::Color outline)
{
    sf::RectangleShape card({rect.width, rect.height});
    card.setPosition(rect.left, rect.top);
    card.setFillColor(palette::kCard);
    card.setOutlineColor(outline);
    card.setOutlineThickness(3.0f * scale);
    target.draw(card);
}

} // namespace abalike::app
