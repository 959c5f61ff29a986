#include "render/Palette.hpp"

#include <algorithm>

namespace abalike::app
{

sf::Color colourOf(const Rgba& rgba)
{
    return {rgba[0], rgba[1], rgba[2], rgba[3]};
}

MaterialColours materialColours(const MaterialLook& look)
{
    return {colourOf(look.fill), colourOf(look.outline), colourOf(look.detail), colourOf(look.highlight)};
}

BirdColours birdColours(const BirdLook& look)
{
    return {colourOf(look.body), colourOf(look.outline), colourOf(look.belly), colourOf(look.brow)};
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
