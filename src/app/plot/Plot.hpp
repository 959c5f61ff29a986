#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace abalike::app
{

/// A colour with components in 0..1.
struct Rgb
{
    double r = 0.0;
    double g = 0.0;
    double b = 0.0;
};

/// How an axis maps values to the page.
enum class AxisScale
{
    Linear, ///< ticks at 1, 2 or 5 times a power of ten
    Log10,  ///< ticks at the decades, minor grid at 2..9; values <= 0 are left out
};

/// One axis: its label, scale and optional fixed ends (unset ends follow the data, rounded out to a tick).
struct PlotAxis
{
    std::string label;
    AxisScale scale = AxisScale::Linear;
    std::optional<double> min;
    std::optional<double> max;
    std::optional<double> tickStep; ///< linear axes: the distance between major ticks (chosen when unset)
};

/// How the points of a series are marked.
enum class Marker
{
    None,
    Disc,
    Square,
    Diamond,
    Triangle,
};

/// One line of a plot: (x, y) points joined in the order given; a non-finite point (or one a log axis cannot show)
/// breaks the line.
struct PlotSeries
{
    std::string label; ///< shown in the legend; an empty label keeps the series out of it
    std::vector<std::pair<double, double>> points;
    Rgb colour;
    Marker marker = Marker::Disc;
    bool dashed = false;
    bool line = true; ///< false draws the markers only
};

/// How a called-out point is drawn.
enum class CalloutStyle
{
    Ring,      ///< a dark ring around a point that is already on a line (e.g. "the preview")
    Highlight, ///< a large filled dot with a white rim, in the callout's colour (e.g. "your aim")
};

/// A single point called out with a short text and a leader line, placed where it covers no data.
struct PlotCallout
{
    double x = 0.0;
    double y = 0.0;
    std::string text;
    CalloutStyle style = CalloutStyle::Ring;
    Rgb colour{0.12, 0.12, 0.14};
    bool guides = false; ///< dashed lines from the point to both axes, to read its coordinates off them
};

/// A line plot: title, axes, series and called-out points. Draw it with savePlotPng.
struct Plot
{
    std::string title;
    std::string subtitle;
    PlotAxis x;
    PlotAxis y;
    std::vector<PlotSeries> series;
    std::vector<PlotCallout> callouts;
};

/// Sizes of the picture and its text, in pixels. The defaults read well at README width.
struct PlotStyle
{
    int widthPx = 1100;
    int heightPx = 760;
    std::string fontFamily = "DejaVu Sans"; ///< looked up through fontconfig (Debian: fonts-dejavu-core)
    double titlePx = 22.0;
    double subtitlePx = 15.0;
    double axisLabelPx = 18.0;
    double tickLabelPx = 17.0;
    double legendPx = 15.0;
    double calloutPx = 15.0;
    double lineWidthPx = 2.2;
    double markerPx = 4.5; ///< marker radius
};

/// A palette of distinct, colour-blind-friendly line colours (Okabe-Ito), repeating after seven.
Rgb plotColour(std::size_t index);

} // namespace abalike::app
