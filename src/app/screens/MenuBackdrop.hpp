#pragma once

#include <SFML/Graphics/RenderTarget.hpp>
#include <string>

namespace abalike::app
{

class AppContext;

/// The backdrop of a menu screen: the menu colour over the window, a title and a line under it, from `top` (a share
/// of the window's height). Returns where the menu below them starts, in pixels.
float drawMenuBackdrop(sf::RenderTarget& target, AppContext& app, const std::string& title, const std::string& subtitle,
                       float top);

} // namespace abalike::app
