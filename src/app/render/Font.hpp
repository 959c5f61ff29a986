#pragma once

#include <SFML/Graphics/Font.hpp>
#include <memory>
#include <string>

namespace abalike::app
{

/// Loads the game font (DejaVu Sans): the file found at build time (ABALIKE_FONT_FILE), then $ABALIKE_FONT, then
/// /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf. When none loads, says so in one line on stderr and returns
/// null; the game then runs without text.
std::unique_ptr<sf::Font> loadGameFont();

/// The game font's file, found the same way (the editor's panels load it into Dear ImGui); empty when none exists.
std::string gameFontPath();

} // namespace abalike::app
