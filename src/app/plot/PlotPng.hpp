#pragma once

#include "plot/Obstacles.hpp"
#include "plot/Plot.hpp"

#include <string>

namespace abalike::app
{

/// Where savePlotPng puts the plot area and the legend, in pixels (y down).
struct PlotPlacement
{
    PixelBox area;
    PixelBox legend;          ///< all zero when no series has a label
    bool legendInside = true; ///< false: no corner inside was free of data, so the legend is right of the plot
};

/// Lays the plot out as savePlotPng would, without drawing it. Throws PlotError when no font is installed.
PlotPlacement placePlot(const Plot& plot, const PlotStyle& style = {});

/// Draws the plot into a PNG file of the style's size, headless (a cairo image surface; text through fontconfig).
/// Throws PlotError when the file cannot be written or no font is installed.
void savePlotPng(const Plot& plot, const std::string& path, const PlotStyle& style = {});

} // namespace abalike::app
