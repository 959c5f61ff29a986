#include "bench/TrueTypeFont.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

namespace abalike::app
{

namespace
{

/// Decodes UTF-8 into code points; invalid bytes become U+FFFD.
std::u32string decodeUtf8(const std::string& text)
{
    std::u32string out;
    for (std::size_t i = 0; i < text.size();)
    {
        const auto b = static_cast<unsigned char>(text[i]);
        int extra = 0;
        char32_t c = 0;
        if (b < 0x80)
            c = b;
        else if ((b >> 5) == 0x6)
            c = b & 0x1F, extra = 1;
        else if ((b >> 4) == 0xE)
            c = b & 0x0F, extra = 2;
        else if ((b >> 3) == 0x1E)
            c = b & 0x07, extra = 3;
        else
            c = 0xFFFD;
        ++i;
        for (int k = 0; k < extra && i < text.size(); ++k, ++i)
            c = (c << 6) | (static_cast<unsigned char>(text[i]) & 0x3F);
        out.push_back(c);
    }
    return out;
}

/// Sub-scanlines per pixel row for anti-aliasing.
constexpr int kSubsamples = 5;
/// Line segments per quadratic curve when flattening.
constexpr int kCurveSegments = 8;

} // namespace

std::uint16_t TrueTypeFont::u16(std::size_t at) const
{
    if (at + 2 > m_data.size())
        return 0;
    return static_cast<std::uint16_t>(m_data[at] << 8 | m_data[at + 1]);
}

std::int16_t TrueTypeFont::s16(std::size_t at) const
{
    return static_cast<std::int16_t>(u16(at));
}

std::uint32_t TrueTypeFont::u32(std::size_t at) const
{
    return static_cast<std::uint32_t>(u16(at)) << 16 | u16(at + 2);
}

std::optional<TrueTypeFont> TrueTypeFont::load(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return std::nullopt;
    TrueTypeFont font;
    font.m_data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (font.m_data.size() < 12)
        return std::nullopt;
    const std::uint16_t tables = font.u16(4);
    for (std::uint16_t i = 0; i < tables; ++i)
    {
        const std::size_t record = 12 + 16u * i;
        const std::string tag(font.m_data.begin() + static_cast<long>(record),
                              font.m_data.begin() + static_cast<long>(record + 4));
        font.m_tables[tag] = font.u32(record + 8);
    }
    for (const char* required : {"head", "hhea", "hmtx", "loca", "glyf", "cmap"})
        if (font.m_tables.count(required) == 0)
            return std::nullopt;
    const std::size_t head = font.m_tables["head"];
    font.m_unitsPerEm = font.u16(head + 18);
    font.m_longLoca = font.s16(head + 50) != 0;
    const std::size_t hhea = font.m_tables["hhea"];
    font.m_ascender = font.s16(hhea + 4);
    font.m_descender = font.s16(hhea + 6);
    font.m_hMetrics = font.u16(hhea + 34);

    const std::size_t cmap = font.m_tables["cmap"];
    const std::uint16_t encodings = font.u16(cmap + 2);
    for (std::uint16_t i = 0; i < encodings; ++i)
    {
        const std::uint16_t platform = font.u16(cmap + 4 + 8u * i);
        const std::uint16_t encoding = font.u16(cmap + 6 + 8u * i);
        const std::size_t subtable = cmap + font.u32(cmap + 8 + 8u * i);
        const bool unicode = platform == 0 || (platform == 3 && encoding == 1);
        if (unicode && font.u16(subtable) == 4)
        {
            font.m_cmap4 = subtable;
            break;
        }
    }
    if (font.m_cmap4 == 0 || font.m_unitsPerEm <= 0.0)
        return std::nullopt;
    return font;
}

std::uint16_t TrueTypeFont::glyphIndex(char32_t c) const
{
    if (c > 0xFFFF)
        return 0;
    const std::size_t t = m_cmap4;
    const std::size_t segments = u16(t + 6) / 2u;
    const std::size_t ends = t + 14;
    const std::size_t starts = ends + 2 * segments + 2;
    const std::size_t deltas = starts + 2 * segments;
    const std::size_t ranges = deltas + 2 * segments;
    for (std::size_t i = 0; i < segments; ++i)
    {
        if (c > u16(ends + 2 * i))
            continue;
        const std::uint16_t start = u16(starts + 2 * i);
        if (c < start)
            return 0;
        const std::uint16_t rangeOffset = u16(ranges + 2 * i);
        if (rangeOffset == 0)
            return static_cast<std::uint16_t>(c + static_cast<std::uint16_t>(u16(deltas + 2 * i)));
        const std::uint16_t glyph = u16(ranges + 2 * i + rangeOffset + 2 * (c - start));
        return glyph == 0 ? 0 : static_cast<std::uint16_t>(glyph + u16(deltas + 2 * i));
    }
    return 0;
}

double TrueTypeFont::advance(std::uint16_t glyph) const
{
    const std::size_t hmtx = m_tables.at("hmtx");
    const std::uint16_t metric = m_hMetrics == 0 ? 0 : std::min<std::uint16_t>(glyph, m_hMetrics - 1);
    return u16(hmtx + 4u * metric);
}

std::vector<TrueTypeFont::Contour> TrueTypeFont::outline(std::uint16_t glyph, int depth) const
{
    std::vector<Contour> contours;
    const std::size_t loca = m_tables.at("loca");
    const std::size_t start = m_longLoca ? u32(loca + 4u * glyph) : 2u * u16(loca + 2u * glyph);
    const std::size_t end = m_longLoca ? u32(loca + 4u * glyph + 4) : 2u * u16(loca + 2u * glyph + 2);
    if (end <= start || depth > 4)
        return contours;
    const std::size_t g = m_tables.at("glyf") + start;
    const std::int16_t contourCount = s16(g);

    if (contourCount < 0)
    {
        // Composite: other glyphs, each moved (and possibly scaled) into place.
        std::size_t at = g + 10;
        for (bool more = true; more;)
        {
            const std::uint16_t flags = u16(at);
            const std::uint16_t component = u16(at + 2);
            at += 4;
            double dx = 0.0, dy = 0.0;
            if ((flags & 0x0001) != 0) // arguments are words
            {
                dx = s16(at), dy = s16(at + 2);
                at += 4;
            }
            else
            {
                dx = static_cast<std::int8_t>(m_data[at]), dy = static_cast<std::int8_t>(m_data[at + 1]);
                at += 2;
            }
            if ((flags & 0x0002) == 0) // point matching instead of offsets: rare in text fonts, ignored
                dx = dy = 0.0;
            double a = 1.0, b = 0.0, c = 0.0, d = 1.0;
            if ((flags & 0x0008) != 0)
                a = d = s16(at) / 16384.0, at += 2;
            else if ((flags & 0x0040) != 0)
                a = s16(at) / 16384.0, d = s16(at + 2) / 16384.0, at += 4;
            else if ((flags & 0x0080) != 0)
                a = s16(at) / 16384.0, b = s16(at + 2) / 16384.0, c = s16(at + 4) / 16384.0, d = s16(at + 6) / 16384.0,
                at += 8;
            for (Contour contour : outline(component, depth + 1))
            {
                for (Point& p : contour)
                    p = {a * p.x + c * p.y + dx, b * p.x + d * p.y + dy};
                contours.push_back(std::move(contour));
            }
            more = (flags & 0x0020) != 0;
        }
        return contours;
    }

    // Simple glyph: contour end points, instructions (skipped), flags, then x and y deltas.
    std::vector<std::uint16_t> endPoints(static_cast<std::size_t>(contourCount));
    for (std::size_t i = 0; i < endPoints.size(); ++i)
        endPoints[i] = u16(g + 10 + 2 * i);
    const std::size_t points = endPoints.empty() ? 0 : endPoints.back() + 1u;
    std::size_t at = g + 10 + 2 * endPoints.size();
    at += 2 + u16(at);
    std::vector<std::uint8_t> flags;
    while (flags.size() < points && at < m_data.size())
    {
        const std::uint8_t flag = m_data[at++];
        flags.push_back(flag);
        if ((flag & 0x08) != 0 && at < m_data.size())
            for (int repeat = m_data[at++]; repeat > 0 && flags.size() < points; --repeat)
                flags.push_back(flag);
    }
    std::vector<Point> raw(points);
    auto readCoordinates = [&](bool isX)
    {
        const std::uint8_t shortBit = isX ? 0x02 : 0x04;
        const std::uint8_t sameBit = isX ? 0x10 : 0x20;
        double value = 0.0;
        for (std::size_t i = 0; i < points; ++i)
        {
            if ((flags[i] & shortBit) != 0)
            {
                const double delta = m_data[at++];
                value += (flags[i] & sameBit) != 0 ? delta : -delta;
            }
            else if ((flags[i] & sameBit) == 0)
            {
                value += s16(at);
                at += 2;
            }
            (isX ? raw[i].x : raw[i].y) = value;
        }
    };
    readCoordinates(true);
    readCoordinates(false);

    std::size_t first = 0;
    for (const std::uint16_t last : endPoints)
    {
        // Quadratic B-spline: between two off-curve points lies an implied on-curve midpoint.
        const std::size_t n = last + 1u - first;
        auto onCurve = [&](std::size_t i)
        {
            return (flags[first + i % n] & 0x01) != 0;
        };
        auto point = [&](std::size_t i)
        {
            return raw[first + i % n];
        };
        std::size_t s = 0;
        while (s < n && !onCurve(s))
            ++s;
        Contour contour;
        Point startPoint = s < n ? point(s) : Point{(point(0).x + point(1).x) / 2, (point(0).y + point(1).y) / 2};
        contour.push_back(startPoint);
        Point current = startPoint;
        for (std::size_t k = 1; k <= n; ++k)
        {
            const std::size_t i = s + k;
            if (onCurve(i))
            {
                current = point(i);
                contour.push_back(current);
                continue;
            }
            const Point control = point(i);
            const Point next = onCurve(i + 1)
                                   ? point(i + 1)
                                   : Point{(control.x + point(i + 1).x) / 2, (control.y + point(i + 1).y) / 2};
            for (int j = 1; j <= kCurveSegments; ++j)
            {
                const double u = static_cast<double>(j) / kCurveSegments;
                const double v = 1.0 - u;
                contour.push_back({v * v * current.x + 2 * u * v * control.x + u * u * next.x,
                                   v * v * current.y + 2 * u * v * control.y + u * u * next.y});
            }
            current = next;
            if (onCurve(i + 1))
                ++k;
        }
        contours.push_back(std::move(contour));
        first = last + 1u;
    }
    return contours;
}

double TrueTypeFont::measure(const std::string& utf8, double pixelSize) const
{
    double width = 0.0;
    for (const char32_t c : decodeUtf8(utf8))
        width += advance(glyphIndex(c));
    return width * pixelSize / m_unitsPerEm;
}

TextBitmap TrueTypeFont::render(const std::string& utf8, double pixelSize) const
{
    const double scale = pixelSize / m_unitsPerEm;
    TextBitmap bitmap;
    bitmap.baselineY = static_cast<int>(std::ceil(m_ascender * scale)) + 1;
    bitmap.height = bitmap.baselineY + static_cast<int>(std::ceil(-m_descender * scale)) + 1;
    bitmap.width = static_cast<int>(std::ceil(measure(utf8, pixelSize))) + 2;
    bitmap.coverage.assign(static_cast<std::size_t>(bitmap.width * bitmap.height), 0.0f);

    // Every glyph's edges in pixel coordinates (y down), then one non-zero-winding scanline fill.
    struct Edge
    {
        double x0, y0, x1, y1;
    };
    std::vector<Edge> edges;
    double penX = 1.0;
    for (const char32_t c : decodeUtf8(utf8))
    {
        const std::uint16_t glyph = glyphIndex(c);
        for (const Contour& contour : outline(glyph))
            for (std::size_t i = 0; i < contour.size(); ++i)
            {
                const Point& a = contour[i];
                const Point& b = contour[(i + 1) % contour.size()];
                edges.push_back({penX + a.x * scale, bitmap.baselineY - a.y * scale, penX + b.x * scale,
                                 bitmap.baselineY - b.y * scale});
            }
        penX += advance(glyph) * scale;
    }

    std::vector<std::pair<double, int>> crossings;
    std::vector<float> row(static_cast<std::size_t>(bitmap.width));
    for (int y = 0; y < bitmap.height; ++y)
    {
        std::fill(row.begin(), row.end(), 0.0f);
        for (int sub = 0; sub < kSubsamples; ++sub)
        {
            const double sy = y + (sub + 0.5) / kSubsamples;
            crossings.clear();
            for (const Edge& e : edges)
            {
                if ((e.y0 <= sy) == (e.y1 <= sy))
                    continue;
                const double x = e.x0 + (sy - e.y0) * (e.x1 - e.x0) / (e.y1 - e.y0);
                crossings.emplace_back(x, e.y1 > e.y0 ? 1 : -1);
            }
            std::sort(crossings.begin(), crossings.end());
            int winding = 0;
            for (std::size_t i = 0; i + 1 < crossings.size(); ++i)
            {
                winding += crossings[i].second;
                if (winding == 0)
                    continue;
                // Exact horizontal coverage of the span [a, b) on this sub-scanline.
                const double a = std::clamp(crossings[i].first, 0.0, static_cast<double>(bitmap.width));
                const double b = std::clamp(crossings[i + 1].first, 0.0, static_cast<double>(bitmap.width));
                for (int x = static_cast<int>(a); x < bitmap.width && x < b; ++x)
                {
                    const double covered = std::min(b, x + 1.0) - std::max(a, static_cast<double>(x));
                    row[static_cast<std::size_t>(x)] += static_cast<float>(std::max(0.0, covered) / kSubsamples);
                }
            }
        }
        for (int x = 0; x < bitmap.width; ++x)
            bitmap.coverage[static_cast<std::size_t>(y * bitmap.width + x)] =
                std::min(1.0f, row[static_cast<std::size_t>(x)]);
    }
    return bitmap;
}

} // namespace abalike::app
