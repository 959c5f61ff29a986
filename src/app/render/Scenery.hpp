#pragma once

#include <SFML/Graphics/Color.hpp>
#include <abalike/level/WorldTheme.hpp>

namespace abalike::app
{

/// The colours of one world's scenery: sky, clouds, the two rows of hills, the ground and its surface layer.
struct Scenery
{
    sf::Color skyTop;
    sf::Color skyBottom;
    sf::Color cloud;    ///< alpha 0: no clouds (no air to hold them)
    bool stars = false; ///< an airless black sky shows stars
    sf::Color hillFar;
    sf::Color hillNear;
    sf::Color ground;
    sf::Color groundDark;
    sf::Color surface; ///< the top layer: grass on Earth, dust or ice elsewhere
    sf::Color surfaceDark;
    bool blades = true; ///< grass blades along the top (Earth only)
    bool bands = false; ///< Jupiter's cloud belts across the sky
};

/// Earth's blue sky and green grass; the Moon's black sky over grey regolith; Mars's butterscotch sky over rust;
/// Titan's orange haze over dark hydrocarbon dunes; Jupiter's banded ochre clouds.
const Scenery& sceneryOf(WorldTheme theme);

} // namespace abalike::app
