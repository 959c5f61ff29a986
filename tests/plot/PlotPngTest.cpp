#include "plot/PlotPng.hpp"
#include "plot/PlotError.hpp"
#include "plot/PlotFont.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>

namespace abalike::app
{
namespace
{

namespace fs = std::filesystem;

/// A PNG read back for its pixels.
class Picture
{
public:
    explicit Picture(const std::string& path)
        : m_surface(cairo_image_surface_create_from_png(path.c_str()), cairo_surface_destroy)
    {
    }
    bool ok() const { return cairo_surface_status(m_surface.get()) == CAIRO_STATUS_SUCCESS; }
    int width() const { return cairo_image_surface_get_width(m_surface.get()); }
    int height() const { return cairo_image_surface_get_height(m_surface.get()); }
    /// 0xRRGGBB at (x, y).
    unsigned pixel(int x, int y) const
    {
        const unsigned char* row =
            cairo_image_surface_get_data(m_surface.get()) + y * cairo_image_surface_get_stride(m_surface.get());
        return reinterpret_cast<const std::uint32_t*>(row)[x] & 0xFFFFFFu;
    }
    /// How many pixels inside the box have exactly this colour.
    int count(unsigned rgb, const PixelBox& box) const
    {
        int n = 0;
        for (int y = static_cast<int>(box.y0); y < static_cast<int>(box.y1); ++y)
            for (int x = static_cast<int>(box.x0); x < static_cast<int>(box.x1); ++x)
                n += pixel(x, y) == rgb ? 1 : 0;
        return n;
    }

private:
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> m_surface;
};

unsigned hex(Rgb c)
{
    auto byte = [](double v)
    {
        return static_cast<unsigned>(std::lround(v * 255.0));
    };
    return byte(c.r) << 16 | byte(c.g) << 8 | byte(c.b);
}

class PlotPngTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        m_dir = fs::temp_directory_path() /
                ("abalike-plot-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }
    std::string file(const std::string& name) const { return (m_dir / name).string(); }

    fs::path m_dir;
};

/// A range chart like `abalike chart range` draws: linear axes with fixed ends, a line, two marked points.
Plot rangeChart()
{
    Plot plot;
    plot.title = "Range against launch angle";
    plot.x.label = "launch angle (degrees)";
    plot.x.min = 0.0;
    plot.x.max = 90.0;
    plot.x.tickStep = 15.0;
    plot.y.label = "range (m)";
    plot.y.min = 0.0;
    plot.y.max = 50.0;
    PlotSeries range;
    range.label = "range at 20 m/s";
    range.colour = plotColour(0);
    range.marker = Marker::None;
    for (int a = 0; a <= 90; ++a)
        range.points.emplace_back(a, 400.0 / 9.81 * std::sin(2.0 * a * 3.14159265358979 / 180.0));
    plot.series.push_back(range);
    plot.callouts.push_back({45.0, 400.0 / 9.81, "best: 45°", CalloutStyle::Ring, {0.1, 0.1, 0.1}, true});
    plot.callouts.push_back({30.0, 400.0 / 9.81 * std::sin(60.0 * 3.14159265358979 / 180.0), "your aim: 30°",
                             CalloutStyle::Highlight, plotColour(1), false});
    return plot;
}

TEST_F(PlotPngTest, FontconfigFindsDejaVuSans)
{
    const PlotFont font = PlotFont::match("DejaVu Sans");
    EXPECT_EQ(font.family(), "DejaVu Sans");
    EXPECT_EQ(fs::path(font.file()).filename(), "DejaVuSans.ttf");
    EXPECT_NE(font.face(), nullptr);
}

TEST_F(PlotPngTest, DrawsAtTheStyleSizeWithPointsWhereTheAxesPutThem)
{
    const Plot plot = rangeChart();
    PlotStyle style;
    style.widthPx = 900;
    style.heightPx = 600;
    savePlotPng(plot, file("range.png"), style);
    const Picture png(file("range.png"));
    ASSERT_TRUE(png.ok());
    EXPECT_EQ(png.width(), 900);
    EXPECT_EQ(png.height(), 600);
    EXPECT_EQ(png.pixel(2, 2), 0xFFFFFFu);

    // Fixed axis ends: the highlighted aim (30°, 35.3 m) sits at 1/3 of the width and 70.6 % of the height.
    const PlotPlacement at = placePlot(plot, style);
    const double x = at.area.x0 + (at.area.x1 - at.area.x0) * 30.0 / 90.0;
    const double y = at.area.y1 - (at.area.y1 - at.area.y0) * plot.callouts[1].y / 50.0;
    const unsigned aim = hex(plotColour(1));
    EXPECT_EQ(png.pixel(static_cast<int>(x), static_cast<int>(y)), aim);
    EXPECT_GT(png.count(aim, {x - 8, y - 8, x + 8, y + 8}), 100);
    EXPECT_EQ(png.count(aim, {0, 0, x - 20, 600}), 0) << "the aim's colour appears nowhere else";
    // The line is drawn along its whole length, inside the plot area only.
    const unsigned line = hex(plotColour(0));
    EXPECT_GT(png.count(line, at.area), 600);
    EXPECT_EQ(png.count(line, {0, 0, at.area.x0 - 1, 600}), 0);
    // The best angle's ring (radius 2.1 marker radii) around (45°, 40.8 m): dark above the point, where nothing else
    // is drawn, and the point itself is the line's.
    const double bx = at.area.x0 + (at.area.x1 - at.area.x0) * 0.5;
    const double by = at.area.y1 - (at.area.y1 - at.area.y0) * (400.0 / 9.81) / 50.0;
    const unsigned ring = png.pixel(static_cast<int>(bx), static_cast<int>(std::lround(by - 2.1 * style.markerPx)));
    EXPECT_LT(ring & 0xFF, 0x60u) << std::hex << ring;
    EXPECT_EQ(png.pixel(static_cast<int>(bx + 3.0), static_cast<int>(by - 5.0)), 0xFFFFFFu) << "inside the ring";
}

TEST_F(PlotPngTest, LegendGoesWhereThereIsNoData)
{
    // Data along the top and the right: the first free corner is the lower left.
    Plot plot;
    plot.x.max = 10.0;
    plot.y.max = 10.0;
    PlotSeries s;
    s.label = "a series with a long enough label";
    s.colour = plotColour(2);
    for (int i = 0; i <= 9; ++i)
        s.points.emplace_back(i, 9.5);
    for (int i = 9; i >= 0; --i)
        s.points.emplace_back(9.5, i);
    plot.series.push_back(s);
    const PlotPlacement at = placePlot(plot);
    ASSERT_TRUE(at.legendInside);
    EXPECT_LT(at.legend.x0 - at.area.x0, 20.0);
    EXPECT_LT(at.area.y1 - at.legend.y1, 20.0);
}

TEST_F(PlotPngTest, LegendMovesOutsideWhenDataFillsThePlot)
{
    Plot plot;
    PlotSeries s;
    s.label = "zigzag";
    s.colour = plotColour(3);
    for (int i = 0; i <= 60; ++i)
        s.points.emplace_back(i, i % 2);
    plot.series.push_back(s);
    const PlotPlacement at = placePlot(plot);
    EXPECT_FALSE(at.legendInside);
    EXPECT_GT(at.legend.x0, at.area.x1);
    EXPECT_LE(at.legend.x1, 1100.0);
    savePlotPng(plot, file("zigzag.png"));
    EXPECT_GT(Picture(file("zigzag.png")).count(hex(plotColour(3)), at.legend), 20) << "the legend's swatch";
}

TEST_F(PlotPngTest, NoLegendWithoutLabels)
{
    Plot plot = rangeChart();
    plot.series[0].label.clear();
    const PlotPlacement at = placePlot(plot);
    EXPECT_EQ(at.legend.x1, 0.0);
}

TEST_F(PlotPngTest, PointsAnAxisCannotShowAreLeftOut)
{
    Plot plot;
    plot.x.scale = AxisScale::Log10;
    plot.y.scale = AxisScale::Log10;
    PlotSeries s;
    s.label = "with gaps";
    s.colour = plotColour(0);
    s.points = {{1.0, 1.0}, {0.0, 5.0}, {-3.0, 2.0}, {std::nan(""), 1.0}, {10.0, INFINITY}, {100.0, 1e-3}};
    plot.series.push_back(s);
    plot.callouts.push_back({-1.0, 1.0, "not shown"});
    savePlotPng(plot, file("gaps.png"));
    EXPECT_TRUE(Picture(file("gaps.png")).ok());

    Plot empty;
    savePlotPng(empty, file("empty.png"));
    EXPECT_TRUE(Picture(file("empty.png")).ok());
}

TEST_F(PlotPngTest, AnUnwritableFileIsAPlotErrorNamingIt)
{
    const std::string path = file("no-such-folder/plot.png");
    try
    {
        savePlotPng(rangeChart(), path);
        FAIL() << "expected a PlotError";
    }
    catch (const PlotError& e)
    {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace abalike::app
