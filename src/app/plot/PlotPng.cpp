#include "plot/PlotPng.hpp"

#include "plot/AxisLayout.hpp"
#include "plot/CairoPng.hpp"
#include "plot/Obstacles.hpp"
#include "plot/PlotError.hpp"
#include "plot/PlotFont.hpp"

#include <cairo.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>

namespace abalike::app
{

namespace
{

constexpr Rgb kPaper{1.0, 1.0, 1.0};
constexpr Rgb kInk{0.12, 0.12, 0.14};
constexpr Rgb kMutedInk{0.35, 0.35, 0.38};
constexpr Rgb kGrid{0.86, 0.87, 0.89};
constexpr Rgb kMinorGrid{0.94, 0.945, 0.95};
constexpr double kPi = 3.14159265358979323846;

enum class Anchor
{
    Left,
    Centre,
    Right,
};

/// Data extents of one axis over the points both axes can show.
struct Extent
{
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
    void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
};

/// A plot laid out on the page: axes, the plot area in pixels, and what maps data onto it.
struct Frame
{
    AxisLayout x;
    AxisLayout y;
    PixelBox area;

    bool shows(double vx, double vy) const { return x.shows(vx) && y.shows(vy); }
    double px(double v) const { return area.x0 + x.fraction(v) * (area.x1 - area.x0); }
    double py(double v) const { return area.y1 - y.fraction(v) * (area.y1 - area.y0); }
};

class Painter
{
public:
    Painter(const Plot& plot, const PlotStyle& style)
        : m_plot(plot), m_style(style), m_font(PlotFont::match(style.fontFamily)),
          m_surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, style.widthPx, style.heightPx),
                    cairo_surface_destroy),
          m_cr(cairo_create(m_surface.get()), cairo_destroy)
    {
        if (cairo_surface_status(m_surface.get()) != CAIRO_STATUS_SUCCESS)
            throw PlotError("cannot make a " + std::to_string(style.widthPx) + "x" + std::to_string(style.heightPx) +
                            " picture for a plot");
        cairo_set_font_face(m_cr.get(), m_font.face());
        // Unhinted metrics: text measures the same at every position, so centred labels stay centred.
        std::unique_ptr<cairo_font_options_t, decltype(&cairo_font_options_destroy)> options(
            cairo_font_options_create(), cairo_font_options_destroy);
        cairo_font_options_set_antialias(options.get(), CAIRO_ANTIALIAS_GRAY);
        cairo_font_options_set_hint_style(options.get(), CAIRO_HINT_STYLE_SLIGHT);
        cairo_font_options_set_hint_metrics(options.get(), CAIRO_HINT_METRICS_OFF);
        cairo_set_font_options(m_cr.get(), options.get());
    }

    /// Lays out the axes, the plot area and the legend.
    void place();
    void draw();
    void write(const std::string& path);
    const PlotPlacement& placement() const { return m_placement; }

private:
    cairo_t* cr() const { return m_cr.get(); }
    void colour(Rgb c, double alpha = 1.0) const { cairo_set_source_rgba(cr(), c.r, c.g, c.b, alpha); }
    double textWidth(const std::string& text, double px) const;
    void text(const std::string& text, double x, double baseline, double px, Anchor anchor, Rgb c,
              bool upwards = false) const;
    void segment(double x0, double y0, double x1, double y1, double width, Rgb c) const;
    void marker(Marker kind, double x, double y, double radius, Rgb c) const;

    Frame layOut(double rightMargin) const;
    Obstacles dataObstacles(const Frame& f) const;
    PixelBox legendSize() const;
    void drawGrid(const Frame& f) const;
    void drawAxes(const Frame& f) const;
    void drawSeries(const Frame& f) const;
    void drawCallouts(const Frame& f, Obstacles& taken) const;
    void drawLegend(const PixelBox& box) const;
    void drawTitles(const Frame& f) const;

    const Plot& m_plot;
    const PlotStyle& m_style;
    PlotFont m_font;
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> m_surface;
    std::unique_ptr<cairo_t, decltype(&cairo_destroy)> m_cr;
    Frame m_frame;
    Obstacles m_taken;
    PlotPlacement m_placement;
};

double Painter::textWidth(const std::string& s, double px) const
{
    cairo_set_font_size(cr(), px);
    cairo_text_extents_t extents;
    cairo_text_extents(cr(), s.c_str(), &extents);
    return extents.x_advance;
}

void Painter::text(const std::string& s, double x, double baseline, double px, Anchor anchor, Rgb c, bool upwards) const
{
    const double width = textWidth(s, px);
    const double shift = anchor == Anchor::Left ? 0.0 : anchor == Anchor::Centre ? width / 2 : width;
    cairo_save(cr());
    cairo_translate(cr(), x, baseline);
    if (upwards)
        cairo_rotate(cr(), -kPi / 2);
    cairo_move_to(cr(), -shift, 0.0);
    colour(c);
    cairo_show_text(cr(), s.c_str());
    cairo_restore(cr());
}

void Painter::segment(double x0, double y0, double x1, double y1, double width, Rgb c) const
{
    cairo_move_to(cr(), x0, y0);
    cairo_line_to(cr(), x1, y1);
    cairo_set_line_width(cr(), width);
    colour(c);
    cairo_stroke(cr());
}

void Painter::marker(Marker kind, double x, double y, double r, Rgb c) const
{
    switch (kind)
    {
    case Marker::None:
        return;
    case Marker::Disc:
        cairo_arc(cr(), x, y, r, 0.0, 2 * kPi);
        break;
    case Marker::Square:
        cairo_rectangle(cr(), x - 0.85 * r, y - 0.85 * r, 1.7 * r, 1.7 * r);
        break;
    case Marker::Diamond:
        cairo_move_to(cr(), x, y - 1.25 * r);
        cairo_line_to(cr(), x + 1.25 * r, y);
        cairo_line_to(cr(), x, y + 1.25 * r);
        cairo_line_to(cr(), x - 1.25 * r, y);
        cairo_close_path(cr());
        break;
    case Marker::Triangle:
        cairo_move_to(cr(), x, y - 1.3 * r);
        cairo_line_to(cr(), x + 1.15 * r, y + 0.7 * r);
        cairo_line_to(cr(), x - 1.15 * r, y + 0.7 * r);
        cairo_close_path(cr());
        break;
    }
    colour(c);
    cairo_fill(cr());
}

Frame Painter::layOut(double rightMargin) const
{
    Extent ex, ey;
    auto add = [&](double x, double y)
    {
        if (axisShows(m_plot.x.scale, x) && axisShows(m_plot.y.scale, y))
            ex.add(x), ey.add(y);
    };
    for (const PlotSeries& s : m_plot.series)
        for (const auto& [x, y] : s.points)
            add(x, y);
    for (const PlotCallout& c : m_plot.callouts)
        add(c.x, c.y);

    Frame f;
    f.x = layoutAxis(m_plot.x, ex.lo, ex.hi, std::max(2, m_style.widthPx / 110));
    f.y = layoutAxis(m_plot.y, ey.lo, ey.hi, std::max(2, m_style.heightPx / 55));

    double tickWidth = 0.0;
    for (const AxisTick& t : f.y.major)
        tickWidth = std::max(tickWidth, textWidth(t.label, m_style.tickLabelPx));
    double top = 24.0;
    if (!m_plot.title.empty())
        top += m_style.titlePx * 1.3;
    if (!m_plot.subtitle.empty())
        top += m_style.subtitlePx * 1.5;
    const double left = 22.0 + (m_plot.y.label.empty() ? 0.0 : m_style.axisLabelPx * 1.5) + tickWidth + 14.0;
    const double bottom = m_style.heightPx -
                          (18.0 + m_style.tickLabelPx * 1.6 + (m_plot.x.label.empty() ? 0 : m_style.axisLabelPx * 1.8));
    // Room for half of the last x label, which is centred on the axis's end.
    const double lastLabel = f.x.major.empty() ? 0.0 : textWidth(f.x.major.back().label, m_style.tickLabelPx) / 2;
    f.area = {left, top, m_style.widthPx - std::max(rightMargin, lastLabel + 12.0), bottom};
    return f;
}

Obstacles Painter::dataObstacles(const Frame& f) const
{
    Obstacles o;
    for (const PlotSeries& s : m_plot.series)
    {
        const std::pair<double, double>* previous = nullptr;
        for (const auto& p : s.points)
        {
            if (!f.shows(p.first, p.second))
            {
                previous = nullptr;
                continue;
            }
            const double x = f.px(p.first), y = f.py(p.second);
            if (s.marker != Marker::None)
                o.addBox({x - m_style.markerPx, y - m_style.markerPx, x + m_style.markerPx, y + m_style.markerPx});
            if (previous != nullptr && s.line)
                o.addSegment(f.px(previous->first), f.py(previous->second), x, y);
            previous = &p;
        }
    }
    for (const PlotCallout& c : m_plot.callouts)
        if (f.shows(c.x, c.y))
        {
            const double r = 2.5 * m_style.markerPx;
            o.addBox({f.px(c.x) - r, f.py(c.y) - r, f.px(c.x) + r, f.py(c.y) + r});
        }
    return o;
}

PixelBox Painter::legendSize() const
{
    double width = 0.0;
    int rows = 0;
    for (const PlotSeries& s : m_plot.series)
        if (!s.label.empty())
            width = std::max(width, textWidth(s.label, m_style.legendPx)), ++rows;
    if (rows == 0)
        return {};
    return {0.0, 0.0, width + 3.6 * m_style.legendPx, rows * 1.7 * m_style.legendPx + 0.9 * m_style.legendPx};
}

void Painter::drawGrid(const Frame& f) const
{
    const PixelBox& a = f.area;
    for (const double v : f.x.minor)
        segment(f.px(v), a.y0, f.px(v), a.y1, 1.0, kMinorGrid);
    for (const double v : f.y.minor)
        segment(a.x0, f.py(v), a.x1, f.py(v), 1.0, kMinorGrid);
    for (const AxisTick& t : f.x.major)
        segment(f.px(t.value), a.y0, f.px(t.value), a.y1, 1.0, kGrid);
    for (const AxisTick& t : f.y.major)
        segment(a.x0, f.py(t.value), a.x1, f.py(t.value), 1.0, kGrid);
}

void Painter::drawAxes(const Frame& f) const
{
    const PixelBox& a = f.area;
    cairo_rectangle(cr(), a.x0, a.y0, a.x1 - a.x0, a.y1 - a.y0);
    cairo_set_line_width(cr(), 1.2);
    colour(kInk);
    cairo_stroke(cr());
    const double px = m_style.tickLabelPx;
    for (const AxisTick& t : f.x.major)
    {
        segment(f.px(t.value), a.y1, f.px(t.value), a.y1 + 6, 1.4, kInk);
        text(t.label, f.px(t.value), a.y1 + 8 + px, px, Anchor::Centre, kInk);
    }
    for (const AxisTick& t : f.y.major)
    {
        segment(a.x0 - 6, f.py(t.value), a.x0, f.py(t.value), 1.4, kInk);
        text(t.label, a.x0 - 10, f.py(t.value) + 0.36 * px, px, Anchor::Right, kInk);
    }
    const double lx = m_style.axisLabelPx;
    text(m_plot.x.label, (a.x0 + a.x1) / 2, a.y1 + 14 + px + 1.3 * lx, lx, Anchor::Centre, kInk);
    text(m_plot.y.label, 18 + lx, (a.y0 + a.y1) / 2, lx, Anchor::Centre, kInk, true);
}

void Painter::drawSeries(const Frame& f) const
{
    cairo_save(cr());
    cairo_rectangle(cr(), f.area.x0, f.area.y0, f.area.x1 - f.area.x0, f.area.y1 - f.area.y0);
    cairo_clip(cr());
    cairo_set_line_join(cr(), CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr(), CAIRO_LINE_CAP_ROUND);
    for (const PlotSeries& s : m_plot.series)
    {
        if (s.line)
        {
            bool open = false;
            for (const auto& [x, y] : s.points)
            {
                if (!f.shows(x, y))
                {
                    open = false;
                    continue;
                }
                if (open)
                    cairo_line_to(cr(), f.px(x), f.py(y));
                else
                    cairo_move_to(cr(), f.px(x), f.py(y));
                open = true;
            }
            const double dash[] = {7.0, 5.0};
            cairo_set_dash(cr(), dash, s.dashed ? 2 : 0, 0.0);
            cairo_set_line_width(cr(), m_style.lineWidthPx);
            colour(s.colour);
            cairo_stroke(cr());
            cairo_set_dash(cr(), nullptr, 0, 0.0);
        }
        for (const auto& [x, y] : s.points)
            if (f.shows(x, y))
                marker(s.marker, f.px(x), f.py(y), m_style.markerPx, s.colour);
    }
    cairo_restore(cr());
}

void Painter::drawCallouts(const Frame& f, Obstacles& taken) const
{
    const double px = m_style.calloutPx;
    for (const PlotCallout& c : m_plot.callouts)
    {
        if (!f.shows(c.x, c.y))
            continue;
        const double x = f.px(c.x), y = f.py(c.y);
        if (c.guides)
        {
            const double dash[] = {4.0, 4.0};
            cairo_set_dash(cr(), dash, 2, 0.0);
            segment(x, y, x, f.area.y1, 1.2, c.colour);
            segment(x, y, f.area.x0, y, 1.2, c.colour);
            cairo_set_dash(cr(), nullptr, 0, 0.0);
        }
        const double ring = 2.1 * m_style.markerPx;
        if (c.style == CalloutStyle::Highlight)
        {
            marker(Marker::Disc, x, y, ring + 2.0, kPaper);
            marker(Marker::Disc, x, y, ring, c.colour);
        }
        else
        {
            cairo_new_path(cr());
            cairo_arc(cr(), x, y, ring, 0.0, 2 * kPi);
            cairo_set_line_width(cr(), 2.0);
            colour(c.colour);
            cairo_stroke(cr());
        }
        if (c.text.empty())
            continue;
        // The text goes to whichever side of the point (lower right first) stays inside and covers nothing.
        const double w = textWidth(c.text, px), h = 1.3 * px, gap = ring + 18.0;
        PixelBox best{};
        int bestHits = std::numeric_limits<int>::max();
        for (const auto& [sx, sy] : {std::pair{1, 1}, {1, -1}, {-1, 1}, {-1, -1}})
        {
            const double bx = sx > 0 ? x + gap : x - gap - w;
            const double by = sy > 0 ? y + gap : y - gap - h;
            const PixelBox box{bx - 3, by - 3, bx + w + 3, by + h + 3};
            const int hits = f.area.contains(box) ? taken.hits(box) : 1000;
            if (hits < bestHits)
                bestHits = hits, best = box;
        }
        taken.addBox(best);
        const double tx = best.x0 + 3, ty = best.y0 + 3;
        const double cornerX = tx + w / 2 < x ? best.x1 : best.x0;
        const double cornerY = ty + h / 2 < y ? best.y1 : best.y0;
        const double angle = std::atan2(cornerY - y, cornerX - x);
        segment(x + ring * std::cos(angle), y + ring * std::sin(angle), cornerX, cornerY, 1.2, kInk);
        text(c.text, tx, ty + 0.95 * px, px, Anchor::Left, kInk);
    }
}

void Painter::drawLegend(const PixelBox& box) const
{
    const double px = m_style.legendPx;
    cairo_rectangle(cr(), box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0);
    colour(kPaper, 0.92);
    cairo_fill_preserve(cr());
    cairo_set_line_width(cr(), 1.0);
    colour(kGrid);
    cairo_stroke(cr());
    double y = box.y0 + 1.3 * px;
    for (const PlotSeries& s : m_plot.series)
    {
        if (s.label.empty())
            continue;
        const double x = box.x0 + 0.6 * px;
        if (s.line)
        {
            const double dash[] = {7.0, 5.0};
            cairo_set_dash(cr(), dash, s.dashed ? 2 : 0, 0.0);
            segment(x, y, x + 2.1 * px, y, m_style.lineWidthPx, s.colour);
            cairo_set_dash(cr(), nullptr, 0, 0.0);
        }
        marker(s.marker, x + 1.05 * px, y, m_style.markerPx, s.colour);
        text(s.label, x + 2.7 * px, y + 0.36 * px, px, Anchor::Left, kInk);
        y += 1.7 * px;
    }
}

void Painter::drawTitles(const Frame& f) const
{
    const double centre = (f.area.x0 + f.area.x1) / 2;
    double baseline = 18.0 + m_style.titlePx;
    if (!m_plot.title.empty())
    {
        text(m_plot.title, centre, baseline, m_style.titlePx, Anchor::Centre, kInk);
        baseline += m_style.subtitlePx * 1.6;
    }
    if (!m_plot.subtitle.empty())
        text(m_plot.subtitle, centre, baseline, m_style.subtitlePx, Anchor::Centre, kMutedInk);
}

void Painter::place()
{
    // The legend goes inside the plot area, in the first corner where it hides no data; failing that, to the right.
    const PixelBox size = legendSize();
    const bool hasLegend = size.x1 > 0.0;
    m_frame = layOut(30.0);
    m_taken = dataObstacles(m_frame);
    m_placement = {m_frame.area, {}, true};
    if (!hasLegend)
        return;
    const double inset = 12.0, w = size.x1, h = size.y1;
    const PixelBox& a = m_frame.area;
    const double cx = (a.x0 + a.x1 - w) / 2;
    for (const auto& [x, y] : {std::pair{a.x1 - inset - w, a.y0 + inset},
                               {a.x0 + inset, a.y0 + inset},
                               {a.x1 - inset - w, a.y1 - inset - h},
                               {a.x0 + inset, a.y1 - inset - h},
                               {cx, a.y0 + inset},
                               {cx, a.y1 - inset - h}})
    {
        const PixelBox box{x, y, x + w, y + h};
        // A few pixels of clearance, so no marker or line touches the legend's edge.
        if (a.contains(box) && m_taken.hits({x - 4.0, y - 4.0, x + w + 4.0, y + h + 4.0}) == 0)
        {
            m_placement.legend = box;
            m_taken.addBox(box);
            return;
        }
    }
    m_frame = layOut(size.x1 + 30.0);
    m_taken = dataObstacles(m_frame);
    m_placement = {m_frame.area,
                   {m_frame.area.x1 + 18.0, m_frame.area.y0, m_frame.area.x1 + 18.0 + w, m_frame.area.y0 + h},
                   false};
}

void Painter::draw()
{
    place();
    colour(kPaper);
    cairo_paint(cr());
    drawGrid(m_frame);
    drawSeries(m_frame);
    drawAxes(m_frame);
    drawCallouts(m_frame, m_taken);
    if (m_placement.legend.x1 > 0.0)
        drawLegend(m_placement.legend);
    drawTitles(m_frame);
}

void Painter::write(const std::string& path)
{
    writeSurfacePng(m_surface.get(), path, "plot");
}

} // namespace

PlotPlacement placePlot(const Plot& plot, const PlotStyle& style)
{
    Painter painter(plot, style);
    painter.place();
    return painter.placement();
}

void savePlotPng(const Plot& plot, const std::string& path, const PlotStyle& style)
{
    Painter painter(plot, style);
    painter.draw();
    painter.write(path);
}

} // namespace abalike::app
