#include "plot/AxisLayout.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace abalike::app
{

namespace
{

constexpr double kLargest = 1e300; ///< the largest magnitude an axis shows

/// 1, 2 or 5 times a power of ten, the smallest at least raw.
double niceStep(double raw)
{
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double m : {1.0, 2.0, 5.0})
        if (m * decade >= raw * (1.0 - 1e-9))
            return m * decade;
    return 10.0 * decade;
}

/// Gives an empty, reversed or zero-width range a width, moving only the ends the axis does not fix.
void widen(double& lo, double& hi, bool fixedLo, bool fixedHi, bool log)
{
    const bool haveLo = std::isfinite(lo), haveHi = std::isfinite(hi);
    if (!haveLo && !haveHi)
    {
        lo = log ? 1.0 : 0.0;
        hi = log ? 10.0 : 1.0;
        return;
    }
    if (!haveLo || (!fixedLo && lo > hi))
        lo = hi;
    else if (!haveHi || (!fixedHi && lo > hi))
        hi = lo;
    else if (lo > hi)
        std::swap(lo, hi);
    if (lo < hi)
        return;
    if (log)
    {
        if (!fixedLo)
            lo /= 10.0;
        if (!fixedHi || lo == hi)
            hi *= 10.0;
        return;
    }
    const double pad = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
    if (!fixedLo)
        lo -= pad;
    if (!fixedHi || lo == hi)
        hi += pad;
}

AxisLayout linearLayout(const PlotAxis& axis, double dataMin, double dataMax, int maxLabels)
{
    AxisLayout out;
    double lo = axis.min.value_or(dataMin);
    double hi = axis.max.value_or(dataMax);
    widen(lo, hi, axis.min.has_value(), axis.max.has_value(), false);
    // Beyond this the span, or an end rounded out to a tick, would overflow a double.
    lo = std::clamp(lo, -kLargest, kLargest);
    hi = std::clamp(hi, -kLargest, kLargest);
    const double span = hi - lo;
    double step = axis.tickStep.value_or(0.0);
    // A missing, non-positive or far too fine step is replaced by a nice one (about six intervals).
    if (!(step > 0.0) || !std::isfinite(step) || span / step > 10.0 * maxLabels)
        step = niceStep(span / 6.0);
    if (!axis.min)
        lo = std::floor(lo / step + 1e-9) * step;
    if (!axis.max)
        hi = std::ceil(hi / step - 1e-9) * step;
    out.lo = lo;
    out.hi = hi;
    const double first = std::ceil(lo / step - 1e-9);
    const double last = std::floor(hi / step + 1e-9);
    const int stride = std::max(1, static_cast<int>(std::ceil((last - first + 1.0) / maxLabels)));
    for (double k = first; k <= last; ++k)
    {
        const double v = k * step;
        const bool labelled = static_cast<long long>(k - first) % stride == 0;
        out.major.push_back({v, labelled ? tickLabel(v, step * stride) : std::string()});
    }
    // Minor grid: fifths of a step of 1 or 5, quarters of a step of 2.
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    const int parts = std::lround(mantissa) == 2 ? 4 : 5;
    const double minorStep = step / parts;
    for (double k = std::ceil(lo / minorStep - 1e-9); k * minorStep <= hi + 1e-9 * minorStep; ++k)
        if (std::lround(k) % parts != 0)
            out.minor.push_back(k * minorStep);
    return out;
}

AxisLayout logLayout(const PlotAxis& axis, double dataMin, double dataMax, int maxLabels)
{
    AxisLayout out;
    out.scale = AxisScale::Log10;
    const bool fixedLo = axis.min && *axis.min > 0.0;
    const bool fixedHi = axis.max && *axis.max > 0.0;
    double lo = fixedLo ? *axis.min : dataMin;
    double hi = fixedHi ? *axis.max : dataMax;
    widen(lo, hi, fixedLo, fixedHi, true);
    lo = std::clamp(lo, 1.0 / kLargest, kLargest);
    hi = std::clamp(hi, 1.0 / kLargest, kLargest);
    if (!fixedLo)
        lo = std::pow(10.0, std::floor(std::log10(lo) + 1e-9));
    if (!fixedHi)
        hi = std::pow(10.0, std::ceil(std::log10(hi) - 1e-9));
    out.lo = lo;
    out.hi = hi;
    const int first = static_cast<int>(std::ceil(std::log10(lo) - 1e-9));
    const int last = static_cast<int>(std::floor(std::log10(hi) + 1e-9));
    const int stride = std::max(1, (last - first + maxLabels) / maxLabels);
    for (int e = first; e <= last; ++e)
        out.major.push_back({std::pow(10.0, e), (e - first) % stride == 0 ? decadeLabel(e) : std::string()});
    // 2..9 times each decade; left out when the decades are too many to show them apart.
    if (last - first <= 40)
        for (int e = first - 1; e <= last; ++e)
            for (int m = 2; m <= 9; ++m)
            {
                const double v = m * std::pow(10.0, e);
                if (v >= lo * (1.0 - 1e-12) && v <= hi * (1.0 + 1e-12))
                    out.minor.push_back(v);
            }
    // Less than a decade shown: label the minor ticks too, or the axis would have one number or none.
    if (out.major.size() < 2)
        for (const double v : out.minor)
            out.major.push_back({v, tickLabel(v, std::pow(10.0, std::floor(std::log10(v) + 1e-9)))});
    std::sort(out.major.begin(), out.major.end(),
              [](const AxisTick& a, const AxisTick& b) { return a.value < b.value; });
    return out;
}

} // namespace

bool axisShows(AxisScale scale, double v)
{
    return std::isfinite(v) && (scale == AxisScale::Linear || v > 0.0);
}

bool AxisLayout::shows(double v) const
{
    return axisShows(scale, v);
}

double AxisLayout::fraction(double v) const
{
    if (scale == AxisScale::Log10)
        return (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
    return (v - lo) / (hi - lo);
}

AxisLayout layoutAxis(const PlotAxis& axis, double dataMin, double dataMax, int maxLabels)
{
    maxLabels = std::max(2, maxLabels);
    return axis.scale == AxisScale::Log10 ? logLayout(axis, dataMin, dataMax, maxLabels)
                                          : linearLayout(axis, dataMin, dataMax, maxLabels);
}

std::string decadeLabel(int exponent)
{
    static const std::array<const char*, 10> kDigits{"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    std::string label = "10";
    if (exponent < 0)
        label += "⁻";
    for (const char d : std::to_string(std::abs(exponent)))
        label += kDigits[static_cast<std::size_t>(d - '0')];
    return label;
}

std::string tickLabel(double value, double step)
{
    // Decimals enough to tell ticks `step` apart; a value within rounding of zero prints as "0", not "-0".
    const int decimals = std::clamp(static_cast<int>(-std::floor(std::log10(step) + 1e-9)), 0, 12);
    if (std::abs(value) < 1e-9 * step)
        value = 0.0;
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, std::abs(value));
    return (value < 0.0 ? "−" : "") + std::string(buffer);
}

} // namespace abalike::app
