#pragma once

#include "bench/Canvas.hpp"

#include <string>
#include <utility>
#include <vector>

namespace abalike::app
{

/// How the points of a plot line are marked.
enum class Marker
{
    Disc,
    Square,
    Diamond,
};

/// One line of a plot: (x, y) points, both > 0, joined in the order given.
struct PlotSeries
{
    std::string label;
    std::vector<std::pair<double, double>> points;
    Rgb colour;
    Marker marker = Marker::Disc;
    bool dashed = false;
};

/// A point called out on the plot with a ring and a short text.
struct PlotNote
{
    double x = 1.0;
    double y = 1.0;
    std::string text;
};

/// A log-log line plot with decade ticks, grid, axis labels and a legend.
struct LogLogPlot
{
    std::string title;
    std::string subtitle;
    std::string xLabel;
    std::string yLabel;
    std::vector<PlotSeries> series;
    std::vector<PlotNote> notes;
};

/// Draws the plot into a PNG of the given size with the font at fontPath; false (with a message on stderr) if the
/// font cannot be read or the file cannot be written.
bool saveLogLogPlot(const LogLogPlot& plot, const std::string& fontPath, const std::string& pngPath, int width = 1100,
                    int height = 760);

/// A palette of distinct, colour-blind-friendly line colours (Okabe-Ito).
Rgb plotColour(std::size_t index);

} // namespace abalike::app
