#pragma once

#include "plot/Plot.hpp"

#include <string>
#include <vector>

namespace abalike::app
{

/// A labelled tick on an axis.
struct AxisTick
{
    double value = 0.0;
    std::string label; ///< empty for a decade skipped to keep labels apart
};

/// An axis's range and ticks, and where a value falls along it.
struct AxisLayout
{
    AxisScale scale = AxisScale::Linear;
    double lo = 0.0; ///< value at the start of the axis
    double hi = 1.0; ///< value at the end
    std::vector<AxisTick> major;
    std::vector<double> minor; ///< finer grid lines between the major ticks

    /// True if the axis can show v (finite, and positive on a log axis).
    bool shows(double v) const;
    /// Where v falls: 0 at lo, 1 at hi (outside 0..1 beyond the ends).
    double fraction(double v) const;
};

/// True if an axis of this scale can show v (finite, and positive on a log axis).
bool axisShows(AxisScale scale, double v);

/// Lays out an axis for data from dataMin to dataMax (over the values the axis can show; +inf and -inf when there
/// are none). Ends the axis fixes are kept; free ends are rounded out to a major tick. At most
/// maxLabels major ticks carry a label.
AxisLayout layoutAxis(const PlotAxis& axis, double dataMin, double dataMax, int maxLabels = 12);

/// "10⁻⁶": a decade as ten with a superscript exponent.
std::string decadeLabel(int exponent);

/// A tick value with as many decimals as the step between ticks needs, and a true minus sign: "−2.5".
std::string tickLabel(double value, double step);

} // namespace abalike::app
