#pragma once

#include <SFML/Graphics/Font.hpp>
#include <memory>

namespace abalike::app
{

/// Loads the game font (DejaVu Sans): the file found at build time (ABALIKE_FONT_FILE), then $ABALIKE_FONT, then
/// /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf. When none loads, says so in one line on stderr and returns
/// null; the game then runs without text.
std::unique_ptr<sf::Font> loadGameFont();

} // namespace abalike::app
