#include "bench/LogLogPlot.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>

namespace abalike::app
{

namespace
{

constexpr Rgb kWhite{1.0f, 1.0f, 1.0f};
constexpr Rgb kInk{0.12f, 0.12f, 0.14f};
constexpr Rgb kGrid{0.86f, 0.87f, 0.89f};
constexpr Rgb kMinorGrid{0.94f, 0.945f, 0.95f};

/// "10⁻⁶" for a decade exponent, with Unicode superscripts.
std::string decadeLabel(int exponent)
{
    static const std::array<const char*, 10> kDigits{"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    std::string label = "10";
    if (exponent < 0)
        label += "⁻";
    const std::string digits = std::to_string(std::abs(exponent));
    for (const char d : digits)
        label += kDigits[static_cast<std::size_t>(d - '0')];
    return label;
}

struct Range
{
    int lo = 0; ///< decade exponents spanned
    int hi = 1;
};

Range decadesOf(const LogLogPlot& plot, bool x)
{
    double lo = std::numeric_limits<double>::infinity();
    double hi = 0.0;
    for (const PlotSeries& s : plot.series)
        for (const auto& [px, py] : s.points)
        {
            const double v = x ? px : py;
            if (v > 0.0 && std::isfinite(v))
                lo = std::min(lo, v), hi = std::max(hi, v);
        }
    if (!(hi > 0.0))
        return {};
    Range r{static_cast<int>(std::floor(std::log10(lo))), static_cast<int>(std::ceil(std::log10(hi)))};
    if (r.hi == r.lo)
        ++r.hi;
    return r;
}

void drawMarker(Canvas& canvas, Marker marker, double x, double y, Rgb colour)
{
    switch (marker)
    {
    case Marker::Disc:
        canvas.disc(x, y, 4.2, colour);
        break;
    case Marker::Square:
        canvas.square(x, y, 3.8, colour);
        break;
    case Marker::Diamond:
        canvas.diamond(x, y, 5.6, colour);
        break;
    }
}

} // namespace

Rgb plotColour(std::size_t index)
{
    static const std::array<Rgb, 7> kColours{{
        {0.0f, 0.447f, 0.698f},   // blue
        {0.835f, 0.369f, 0.0f},   // vermillion
        {0.0f, 0.62f, 0.451f},    // bluish green
        {0.8f, 0.475f, 0.655f},   // reddish purple
        {0.902f, 0.624f, 0.0f},   // orange
        {0.337f, 0.706f, 0.914f}, // sky blue
        {0.3f, 0.3f, 0.3f},       // grey
    }};
    return kColours[index % kColours.size()];
}

bool saveLogLogPlot(const LogLogPlot& plot, const std::string& fontPath, const std::string& pngPath, int width,
                    int height)
{
    const auto font = TrueTypeFont::load(fontPath);
    if (!font)
    {
        std::cerr << "abalike: cannot read the font " << (fontPath.empty() ? "(none found)" : fontPath)
                  << "; the plot needs DejaVu Sans (Debian: fonts-dejavu-core)\n";
        return false;
    }
    Canvas canvas(width, height, kWhite);
    double legendWidth = 0.0;
    for (const PlotSeries& s : plot.series)
        legendWidth = std::max(legendWidth, font->measure(s.label, 15));
    const double left = 110.0, right = width - legendWidth - 80.0, top = 78.0, bottom = height - 80.0;
    const Range xr = decadesOf(plot, true);
    const Range yr = decadesOf(plot, false);
    auto toX = [&](double v)
    {
        return left + (std::log10(v) - xr.lo) / (xr.hi - xr.lo) * (right - left);
    };
    auto toY = [&](double v)
    {
        return bottom - (std::log10(v) - yr.lo) / (yr.hi - yr.lo) * (bottom - top);
    };

    // Grid: minor lines at 2..9 x each decade, major lines at the decades.
    for (int e = xr.lo; e < xr.hi; ++e)
        for (int m = 2; m <= 9; ++m)
        {
            const double x = toX(m * std::pow(10.0, e));
            canvas.line(x, top, x, bottom, 1.0, kMinorGrid);
        }
    for (int e = yr.lo; e < yr.hi; ++e)
        for (int m = 2; m <= 9; ++m)
        {
            const double y = toY(m * std::pow(10.0, e));
            canvas.line(left, y, right, y, 1.0, kMinorGrid);
        }
    const int xStride = std::max(1, (xr.hi - xr.lo + 7) / 8);
    const int yStride = std::max(1, (yr.hi - yr.lo + 11) / 12);
    for (int e = xr.lo; e <= xr.hi; ++e)
    {
        const double x = toX(std::pow(10.0, e));
        canvas.line(x, top, x, bottom, 1.0, kGrid);
        canvas.line(x, bottom, x, bottom + 6, 1.4, kInk);
        if ((e - xr.lo) % xStride == 0)
            canvas.text(font->render(decadeLabel(e), 17), x, bottom + 27, kInk, TextAnchor::Centre);
    }
    for (int e = yr.lo; e <= yr.hi; ++e)
    {
        const double y = toY(std::pow(10.0, e));
        canvas.line(left, y, right, y, 1.0, kGrid);
        canvas.line(left - 6, y, left, y, 1.4, kInk);
        if ((e - yr.lo) % yStride == 0)
            canvas.text(font->render(decadeLabel(e), 17), left - 10, y + 6, kInk, TextAnchor::Right);
    }
    canvas.line(left, top, left, bottom, 1.6, kInk);
    canvas.line(left, bottom, right, bottom, 1.6, kInk);
    canvas.line(right, top, right, bottom, 1.0, kInk);
    canvas.line(left, top, right, top, 1.0, kInk);

    canvas.text(font->render(plot.title, 22), (left + right) / 2, 34, kInk, TextAnchor::Centre);
    if (!plot.subtitle.empty())
        canvas.text(font->render(plot.subtitle, 15), (left + right) / 2, 58, {0.35f, 0.35f, 0.38f}, TextAnchor::Centre);
    canvas.text(font->render(plot.xLabel, 18), (left + right) / 2, height - 22, kInk, TextAnchor::Centre);
    canvas.text(font->render(plot.yLabel, 18), 30, (top + bottom) / 2, kInk, TextAnchor::Centre, true);

    for (const PlotSeries& s : plot.series)
    {
        for (std::size_t i = 1; i < s.points.size(); ++i)
            canvas.line(toX(s.points[i - 1].first), toY(s.points[i - 1].second), toX(s.points[i].first),
                        toY(s.points[i].second), 2.2, s.colour, s.dashed ? 7.0 : 0.0);
        for (const auto& [x, y] : s.points)
            drawMarker(canvas, s.marker, toX(x), toY(y), s.colour);
    }

    for (const PlotNote& note : plot.notes)
    {
        const double x = toX(note.x);
        const double y = toY(note.y);
        for (double r = 8.5; r < 10.5; r += 0.5)
            for (int i = 0; i < 48; ++i)
            {
                const double a0 = i * 2 * 3.14159265358979 / 48, a1 = (i + 1) * 2 * 3.14159265358979 / 48;
                canvas.line(x + r * std::cos(a0), y + r * std::sin(a0), x + r * std::cos(a1), y + r * std::sin(a1), 0.8,
                            kInk);
            }
        canvas.line(x + 7, y + 7, x + 28, y + 28, 1.2, kInk);
        canvas.text(font->render(note.text, 15), x + 30, y + 44, kInk, TextAnchor::Left);
    }

    // Legend to the right of the plot area.
    double ly = top + 12;
    for (const PlotSeries& s : plot.series)
    {
        const double lx = right + 18;
        canvas.line(lx, ly, lx + 34, ly, 2.2, s.colour, s.dashed ? 7.0 : 0.0);
        drawMarker(canvas, s.marker, lx + 17, ly, s.colour);
        canvas.text(font->render(s.label, 15), lx + 44, ly + 5, kInk, TextAnchor::Left);
        ly += 25;
    }
    return canvas.savePng(pngPath);
}

} // namespace abalike::app
