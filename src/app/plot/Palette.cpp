#include "plot/Plot.hpp"

#include <array>

namespace abalike::app
{

Rgb plotColour(std::size_t index)
{
    static const std::array<Rgb, 7> kColours{{
        {0.0, 0.447, 0.698},   // blue
        {0.835, 0.369, 0.0},   // vermillion
        {0.0, 0.62, 0.451},    // bluish green
        {0.8, 0.475, 0.655},   // reddish purple
        {0.902, 0.624, 0.0},   // orange
        {0.337, 0.706, 0.914}, // sky blue
        {0.3, 0.3, 0.3},       // grey
    }};
    return kColours[index % kColours.size()];
}

} // namespace abalike::app
