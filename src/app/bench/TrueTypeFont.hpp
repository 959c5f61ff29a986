#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

/// A coverage bitmap (0..1 per pixel) of rendered text, with the baseline's position inside it.
struct TextBitmap
{
    int width = 0;
    int height = 0;
    int baselineY = 0; ///< row of the baseline, from the top
    std::vector<float> coverage;

    float at(int x, int y) const { return coverage[static_cast<std::size_t>(y * width + x)]; }
};

/// Just enough of a TrueType reader to draw plot labels without a display: glyph outlines from 'glyf' (simple and
/// composite), character mapping from a format 4 'cmap', advances from 'hmtx', and an anti-aliased scanline fill.
/// No hinting and no kerning. SFML's own text needs an OpenGL context, which a headless benchmark does not have.
class TrueTypeFont
{
public:
    /// Reads a .ttf file; nullopt if it cannot be read or is not a TrueType font with glyph outlines.
    static std::optional<TrueTypeFont> load(const std::string& path);

    /// Renders a line of text (ASCII and the Basic Multilingual Plane) at a pixel size (the em height).
    TextBitmap render(const std::string& utf8, double pixelSize) const;

    /// Width in pixels the text would take at that size.
    double measure(const std::string& utf8, double pixelSize) const;

private:
    struct Point
    {
        double x = 0.0;
        double y = 0.0;
    };
    using Contour = std::vector<Point>;

    std::uint16_t u16(std::size_t at) const;
    std::int16_t s16(std::size_t at) const;
    std::uint32_t u32(std::size_t at) const;
    std::uint16_t glyphIndex(char32_t c) const;
    double advance(std::uint16_t glyph) const;
    /// The glyph's outline in font units, quadratic curves flattened into polygons.
    std::vector<Contour> outline(std::uint16_t glyph, int depth = 0) const;

    std::vector<std::uint8_t> m_data;
    std::map<std::string, std::size_t> m_tables; ///< tag -> offset
    std::size_t m_cmap4 = 0;                     ///< offset of the format 4 subtable
    double m_unitsPerEm = 2048.0;
    double m_ascender = 0.0;
    double m_descender = 0.0;
    bool m_longLoca = false;
    std::uint16_t m_hMetrics = 0;
};

} // namespace abalike::app
