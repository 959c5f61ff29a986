#pragma once

#include "bench/TrueTypeFont.hpp"

#include <string>
#include <vector>

namespace abalike::app
{

/// A colour with components in 0..1.
struct Rgb
{
    float r = 0.0f;
    float g = 0.0f;
    float b = 0.0f;
};

/// Where a piece of text sits relative to the point it is drawn at.
enum class TextAnchor
{
    Left,
    Centre,
    Right,
};

/// A small CPU raster for report figures: anti-aliased lines, markers and text, saved as PNG through sf::Image
/// (which needs no window or OpenGL context, so benchmarks can draw plots headless).
class Canvas
{
public:
    Canvas(int width, int height, Rgb background);

    int width() const { return m_width; }
    int height() const { return m_height; }

    void fillRect(double x0, double y0, double x1, double y1, Rgb colour);
    /// A segment of the given width (px); dashLength > 0 draws it dashed.
    void line(double x0, double y0, double x1, double y1, double width, Rgb colour, double dashLength = 0.0);
    void disc(double cx, double cy, double radius, Rgb colour);
    void square(double cx, double cy, double halfSide, Rgb colour);
    void diamond(double cx, double cy, double radius, Rgb colour);
    /// Draws rendered text with its baseline at y; rotated turns it 90 degrees counter-clockwise (for a y label).
    void text(const TextBitmap& bitmap, double x, double y, Rgb colour, TextAnchor anchor, bool rotated = false);

    /// Writes a PNG; false (and a line on stderr) if it cannot.
    bool savePng(const std::string& path) const;

private:
    void blend(int x, int y, Rgb colour, float alpha);

    int m_width;
    int m_height;
    std::vector<Rgb> m_pixels;
};

} // namespace abalike::app
