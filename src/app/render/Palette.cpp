#include "render/Palette.hpp"

#include <algorithm>

namespace abalike::app
{

MaterialColours materialColours(std::string_view material)
{
    if (material == "wood")
        return {{198, 140, 78}, {116, 72, 34}, {158, 104, 52}, {222, 172, 112}};
    if (material == "ice")
        return {{178, 224, 250, 185}, {110, 172, 214}, {150, 204, 236, 200}, {255, 255, 255, 200}};
    if (material == "stone")
        return {{150, 151, 158}, {82, 83, 90}, {112, 113, 120}, {190, 191, 198}};
    if (material == "tnt")
        return {{196, 52, 36}, {96, 22, 14}, {150, 36, 24}, {250, 226, 160}};
    return {{214, 190, 140}, {140, 118, 80}, {186, 160, 112}, {236, 218, 180}};
}

BirdColours birdColours(std::string_view bird)
{
    if (bird == "blue")
        return {{78, 150, 232}, {36, 82, 150}, {200, 228, 250}, {30, 40, 70}};
    if (bird == "yellow")
        return {{250, 212, 40}, {170, 130, 10}, {255, 240, 170}, {60, 40, 10}};
    if (bird == "black")
        return {{44, 44, 50}, {12, 12, 16}, {84, 84, 92}, {150, 150, 158}};
    if (bird == "white")
        return {{244, 244, 238}, {150, 150, 140}, {255, 255, 255}, {30, 30, 30}};
    return {{214, 36, 36}, {120, 14, 14}, {240, 214, 180}, {24, 14, 10}};
}

sf::Color darken(sf::Color colour, float factor)
{
    const auto scale = [factor](sf::Uint8 c)
    {
        return static_cast<sf::Uint8>(std::clamp(static_cast<float>(c) * factor, 0.0f, 255.0f));
    };
    return {scale(colour.r), scale(colour.g), scale(colour.b), colour.a};
}

sf::Color faded(sf::Color colour, float factor)
{
    colour.a = static_cast<sf::Uint8>(std::clamp(static_cast<float>(colour.a) * factor, 0.0f, 255.0f));
    return colour;
}

} // namespace abalike::app
