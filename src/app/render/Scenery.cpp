#include "render/Scenery.hpp"

#include "render/Palette.hpp"

namespace abalike::app
{

const Scenery& sceneryOf(WorldTheme theme)
{
    static const Scenery earth{palette::kSkyTop,
                               palette::kSkyBottom,
                               palette::kCloud,
                               false,
                               sf::Color(176, 212, 206),
                               sf::Color(150, 200, 150),
                               palette::kEarth,
                               palette::kEarthDark,
                               palette::kGrass,
                               palette::kGrassDark,
                               true};
    static const Scenery moon{sf::Color(6, 8, 20),
                              sf::Color(34, 38, 58),
                              sf::Color(0, 0, 0, 0),
                              true,
                              sf::Color(58, 60, 72),
                              sf::Color(84, 86, 96),
                              sf::Color(86, 86, 92),
                              sf::Color(62, 62, 68),
                              sf::Color(168, 168, 172),
                              sf::Color(138, 138, 144),
                              false};
    static const Scenery mars{sf::Color(196, 148, 112),
                              sf::Color(232, 190, 150),
                              sf::Color(240, 214, 190, 120),
                              false,
                              sf::Color(196, 120, 84),
                              sf::Color(172, 92, 60),
                              sf::Color(150, 72, 44),
                              sf::Color(116, 54, 34),
                              sf::Color(200, 110, 70),
                              sf::Color(168, 86, 52),
                              false};
    static const Scenery titan{sf::Color(176, 118, 46),
                               sf::Color(222, 170, 92),
                               sf::Color(236, 190, 120, 150),
                               false,
                               sf::Color(150, 110, 70),
                               sf::Color(120, 88, 56),
                               sf::Color(84, 62, 44),
                               sf::Color(60, 44, 32),
                               sf::Color(110, 86, 58),
                               sf::Color(88, 68, 46),
                               false};
    static const Scenery jupiter{sf::Color(178, 132, 96),
                                 sf::Color(236, 214, 180),
                                 sf::Color(250, 236, 214, 170),
                                 false,
                                 sf::Color(204, 150, 110),
                                 sf::Color(186, 120, 86),
                                 sf::Color(168, 120, 88),
                                 sf::Color(132, 92, 66),
                                 sf::Color(222, 190, 150),
                                 sf::Color(196, 160, 120),
                                 false,
                                 true};
    switch (theme)
    {
    case WorldTheme::Moon:
        return moon;
    case WorldTheme::Mars:
        return mars;
    case WorldTheme::Titan:
        return titan;
    case WorldTheme::Jupiter:
        return jupiter;
    case WorldTheme::Earth:
        break;
    }
    return earth;
}

} // namespace abalike::app
