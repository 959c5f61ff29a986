#pragma once

#include <SFML/Graphics/Color.hpp>
#include <SFML/Graphics/Rect.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

namespace abalike::app
{

/// Darkens the whole window behind a menu or card, so its text keeps its contrast whatever is under it.
void drawScrim(sf::RenderTarget& target);

/// A card: a solid panel with an outline, the background of menus and dialogs.
void drawCard(sf::RenderTarget& target, sf::FloatRect rect, float scale, sf::Color outline);

} // namespace abalike::app
