#pragma once

#include <SFML/Graphics/RenderWindow.hpp>
#include <string>

namespace abalike::app
{

/// Saves what has been drawn into the window (call before display()) as an image file; the extension picks the
/// format. On failure prints one line on stderr and returns false.
bool saveScreenshot(const sf::RenderWindow& window, const std::string& path);

} // namespace abalike::app
