#pragma once

#include "render/Label.hpp"
#include "render/ScreenRegions.hpp"

#include <SFML/System/Vector2.hpp>
#include <vector>

namespace abalike::app
{

/// Where one frame put what it draws over the world: the layout tests' view of a frame (FrameObserver).
struct FrameLayout
{
    long long frame = 0;
    sf::Vector2u window;
    std::vector<ScreenRegion> panels;      ///< every panel drawn over the world, in drawing order
    std::vector<ScreenRegion> keepVisible; ///< what the panels should leave visible (slingshot, flying bird, pigs)
    std::vector<DrawnText> texts;          ///< every text the frame draws, in drawing order
};

} // namespace abalike::app
