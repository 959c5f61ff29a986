#pragma once

#include <SFML/Graphics/RenderTarget.hpp>

namespace abalike::app
{

/// The title screen's picture, drawn with the game's own painters over the dimmed first level: a red bird flying
/// from the slingshot along its dotted arc, and a grinning helmet pig on the right. It keeps clear
/// of the middle of the window, where the title and the menu are.
void drawTitleArt(sf::RenderTarget& target, float uiScale);

} // namespace abalike::app
