#pragma once

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <string>

namespace abalike::app
{

/// What a loading card says and how far the work has come.
struct Progress
{
    std::string title;     ///< "Loading Level 1-1: First Flight"
    std::string detail;    ///< what is being done, e.g. the settle step's sub-step
    float fraction = 0.0f; ///< 0 to 1
};

/// A card in the middle of the window with a title, a line of detail and a progress bar, over a plain sky: what a
/// load that takes longer than a moment shows. font may be null (the bar is still drawn).
void drawProgressCard(sf::RenderTarget& target, const sf::Font* font, const Progress& progress, unsigned titleSize,
                      unsigned detailSize, float scale);

} // namespace abalike::app
