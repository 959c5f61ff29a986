#include "bench/Canvas.hpp"

#include <SFML/Graphics/Image.hpp>
#include <SFML/System/Err.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace abalike::app
{

Canvas::Canvas(int width, int height, Rgb background)
    : m_width(width), m_height(height), m_pixels(static_cast<std::size_t>(width * height), background)
{
}

void Canvas::blend(int x, int y, Rgb colour, float alpha)
{
    if (x < 0 || y < 0 || x >= m_width || y >= m_height || alpha <= 0.0f)
        return;
    alpha = std::min(alpha, 1.0f);
    Rgb& p = m_pixels[static_cast<std::size_t>(y * m_width + x)];
    p.r += (colour.r - p.r) * alpha;
    p.g += (colour.g - p.g) * alpha;
    p.b += (colour.b - p.b) * alpha;
}

void Canvas::fillRect(double x0, double y0, double x1, double y1, Rgb colour)
{
    for (int y = static_cast<int>(std::floor(y0)); y < static_cast<int>(std::ceil(y1)); ++y)
        for (int x = static_cast<int>(std::floor(x0)); x < static_cast<int>(std::ceil(x1)); ++x)
        {
            // Partial coverage at the edges keeps thin rectangles crisp but not jagged.
            const double cx = std::min(x + 1.0, x1) - std::max(static_cast<double>(x), x0);
            const double cy = std::min(y + 1.0, y1) - std::max(static_cast<double>(y), y0);
            blend(x, y, colour, static_cast<float>(std::max(0.0, cx) * std::max(0.0, cy)));
        }
}

void Canvas::line(double x0, double y0, double x1, double y1, double width, Rgb colour, double dashLength)
{
    const double dx = x1 - x0;
    const double dy = y1 - y0;
    const double length2 = dx * dx + dy * dy;
    const double length = std::sqrt(length2);
    const double reach = width / 2 + 1.0;
    const int left = static_cast<int>(std::floor(std::min(x0, x1) - reach));
    const int right = static_cast<int>(std::ceil(std::max(x0, x1) + reach));
    const int top = static_cast<int>(std::floor(std::min(y0, y1) - reach));
    const int bottom = static_cast<int>(std::ceil(std::max(y0, y1) + reach));
    for (int y = std::max(top, 0); y <= std::min(bottom, m_height - 1); ++y)
        for (int x = std::max(left, 0); x <= std::min(right, m_width - 1); ++x)
        {
            // Coverage from the distance of the pixel centre to the segment.
            const double px = x + 0.5 - x0;
            const double py = y + 0.5 - y0;
            const double u = length2 > 0.0 ? std::clamp((px * dx + py * dy) / length2, 0.0, 1.0) : 0.0;
            if (dashLength > 0.0 && std::fmod(u * length, 2.0 * dashLength) > dashLength)
                continue;
            const double distance = std::hypot(px - u * dx, py - u * dy);
            blend(x, y, colour, static_cast<float>(std::clamp(width / 2 + 0.5 - distance, 0.0, 1.0)));
        }
}

void Canvas::disc(double cx, double cy, double radius, Rgb colour)
{
    for (int y = static_cast<int>(cy - radius - 1); y <= static_cast<int>(cy + radius + 1); ++y)
        for (int x = static_cast<int>(cx - radius - 1); x <= static_cast<int>(cx + radius + 1); ++x)
        {
            const double distance = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
            blend(x, y, colour, static_cast<float>(std::clamp(radius + 0.5 - distance, 0.0, 1.0)));
        }
}

void Canvas::square(double cx, double cy, double halfSide, Rgb colour)
{
    fillRect(cx - halfSide, cy - halfSide, cx + halfSide, cy + halfSide, colour);
}

void Canvas::diamond(double cx, double cy, double radius, Rgb colour)
{
    for (int y = static_cast<int>(cy - radius - 1); y <= static_cast<int>(cy + radius + 1); ++y)
        for (int x = static_cast<int>(cx - radius - 1); x <= static_cast<int>(cx + radius + 1); ++x)
        {
            // |dx| + |dy| is the diamond's own distance; divided by sqrt 2 it is the distance in pixels.
            const double inside = (radius - std::abs(x + 0.5 - cx) - std::abs(y + 0.5 - cy)) / std::sqrt(2.0);
            blend(x, y, colour, static_cast<float>(std::clamp(inside + 0.5, 0.0, 1.0)));
        }
}

void Canvas::text(const TextBitmap& bitmap, double x, double y, Rgb colour, TextAnchor anchor, bool rotated)
{
    const double along = anchor == TextAnchor::Left     ? 0.0
                         : anchor == TextAnchor::Centre ? bitmap.width / 2.0
                                                        : bitmap.width;
    for (int by = 0; by < bitmap.height; ++by)
        for (int bx = 0; bx < bitmap.width; ++bx)
        {
            const float alpha = bitmap.at(bx, by);
            if (alpha <= 0.0f)
                continue;
            if (!rotated)
                blend(static_cast<int>(std::lround(x - along)) + bx,
                      static_cast<int>(std::lround(y)) - bitmap.baselineY + by, colour, alpha);
            else
                // Reads bottom to top: text x runs up the canvas, text y runs right.
                blend(static_cast<int>(std::lround(x)) - bitmap.baselineY + by,
                      static_cast<int>(std::lround(y + along)) - bx, colour, alpha);
        }
}

bool Canvas::savePng(const std::string& path) const
{
    sf::Image image;
    image.create(static_cast<unsigned>(m_width), static_cast<unsigned>(m_height));
    auto byte = [](float v)
    {
        return static_cast<sf::Uint8>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    };
    for (int y = 0; y < m_height; ++y)
        for (int x = 0; x < m_width; ++x)
        {
            const Rgb& p = m_pixels[static_cast<std::size_t>(y * m_width + x)];
            image.setPixel(static_cast<unsigned>(x), static_cast<unsigned>(y),
                           sf::Color(byte(p.r), byte(p.g), byte(p.b)));
        }
    std::streambuf* const sfmlErrors = sf::err().rdbuf(nullptr);
    const bool saved = image.saveToFile(path);
    sf::err().rdbuf(sfmlErrors);
    if (!saved)
        std::cerr << "abalike: cannot write " << path << "\n";
    return saved;
}

} // namespace abalike::app
