#include "render/Label.hpp"

#include "render/FontMetrics.hpp"
#include "render/ScreenRegions.hpp"

#include <SFML/Graphics/Vertex.hpp>
#include <algorithm>
#include <cmath>

namespace abalike::app
{

sf::String utf8(std::string_view text)
{
    return sf::String::fromUtf8(text.begin(), text.end());
}

namespace
{
/// Lays a line of text out as sf::Text does in its regular style (kerning, spaces, tabs and new lines alike), calling
/// visit(glyph, pen) for each visible glyph with the pen at its baseline. Returns the right edge sf::Text's local
/// bounds report (left + width). One pass, no sf::Text: a frame lays out a few hundred labels.
template <class Visit>
float layoutGlyphs(const sf::Font& font, const sf::String& text, unsigned size, Visit&& visit)
{
    FontMetrics& metrics = FontMetrics::of(font);
    const float whitespace = font.getGlyph(U' ', size, false).advance;
    const float lineSpacing = metrics.lineSpacing(size);
    float x = 0.0f;
    auto y = static_cast<float>(size);
    float right = 0.0f;
    sf::Uint32 previous = 0;
    for (const sf::Uint32 current : text)
    {
        if (current == U'\r')
            continue;
        x += metrics.kerning(previous, current, size);
        previous = current;
        if (current == U' ' || current == U'\t' || current == U'\n')
        {
            if (current == U' ')
                x += whitespace;
            else if (current == U'\t')
                x += 4.0f * whitespace;
            else
            {
                y += lineSpacing;
                x = 0.0f;
            }
            right = std::max(right, x);
            continue;
        }
        const sf::Glyph& glyph = font.getGlyph(current, size, false);
        visit(glyph, sf::Vector2f(x, y));
        right = std::max(right, x + glyph.bounds.left + glyph.bounds.width);
        x += glyph.advance;
    }
    return right;
}

/// Two triangles for a glyph with a pixel of padding around it, as sf::Text draws them (the padding keeps the
/// glyph's antialiased edge).
void appendGlyphQuad(std::vector<sf::Vertex>& vertices, sf::Vector2f pen, const sf::Glyph& glyph, sf::Color colour)
{
    constexpr float kPadding = 1.0f;
    const float left = pen.x + glyph.bounds.left - kPadding;
    const float top = pen.y + glyph.bounds.top - kPadding;
    const float right = pen.x + glyph.bounds.left + glyph.bounds.width + kPadding;
    const float bottom = pen.y + glyph.bounds.top + glyph.bounds.height + kPadding;
    const float u1 = static_cast<float>(glyph.textureRect.left) - kPadding;
    const float v1 = static_cast<float>(glyph.textureRect.top) - kPadding;
    const float u2 = static_cast<float>(glyph.textureRect.left + glyph.textureRect.width) + kPadding;
    const float v2 = static_cast<float>(glyph.textureRect.top + glyph.textureRect.height) + kPadding;
    vertices.emplace_back(sf::Vector2f(left, top), colour, sf::Vector2f(u1, v1));
    vertices.emplace_back(sf::Vector2f(right, top), colour, sf::Vector2f(u2, v1));
    vertices.emplace_back(sf::Vector2f(left, bottom), colour, sf::Vector2f(u1, v2));
    vertices.emplace_back(sf::Vector2f(left, bottom), colour, sf::Vector2f(u1, v2));
    vertices.emplace_back(sf::Vector2f(right, top), colour, sf::Vector2f(u2, v1));
    vertices.emplace_back(sf::Vector2f(right, bottom), colour, sf::Vector2f(u2, v2));
}
} // namespace

sf::Vector2f measureText(const sf::Font& font, const sf::String& text, unsigned size)
{
    FontMetrics& metrics = FontMetrics::of(font);
    const float right = metrics.width(
        text, size, [&] { return layoutGlyphs(font, text, size, [](const sf::Glyph&, sf::Vector2f) {}); });
    return {right, metrics.lineSpacing(size)};
}

std::vector<std::string> wrapText(const sf::Font& font, std::string_view text, unsigned size, float maxWidth)
{
    std::vector<std::string> lines;
    std::string line;
    std::size_t start = 0;
    while (start <= text.size())
    {
        const std::size_t end = std::min(text.find(' ', start), text.size());
        const std::string word(text.substr(start, end - start));
        const std::string candidate = line.empty() ? word : line + " " + word;
        if (!line.empty() && measureText(font, utf8(candidate), size).x > maxWidth)
        {
            lines.push_back(line);
            line = word;
        }
        else
            line = candidate;
        start = end + 1;
    }
    if (!line.empty())
        lines.push_back(line);
    return lines;
}

std::vector<std::string> wrapWholeSentences(const sf::Font& font, std::string_view text, unsigned size, float maxWidth,
                                            std::size_t maxLines)
{
    std::vector<std::string> best;
    for (std::size_t end = 0; end < text.size();)
    {
        std::size_t next = text.size();
        for (const char* stop : {". ", "? ", "! "})
            if (const std::size_t at = text.find(stop, end + 1); at != std::string_view::npos)
                next = std::min(next, at + 1); // the sentence keeps its stop

        std::vector<std::string> lines = wrapText(font, text.substr(0, next), size, maxWidth);
        if (lines.size() > maxLines)
            break;
        best = std::move(lines);
        end = next;
    }
    return best;
}

std::string fitToWidth(const sf::Font& font, std::string_view text, unsigned size, float maxWidth, Cut cut)
{
    const auto fits = [&](std::string_view line)
    {
        return measureText(font, utf8(line), size).x <= maxWidth;
    };
    if (fits(text))
        return std::string(text);
    const auto isCut = [&](std::size_t end)
    {
        if (cut == Cut::AtWord)
            return text[end] == ' ';
        return (static_cast<unsigned char>(text[end]) & 0xC0) != 0x80; // not a UTF-8 continuation byte
    };
    std::string best = cut == Cut::AtCharacter ? "\u2026" : "";
    for (std::size_t end = 1; end < text.size(); ++end)
    {
        if (!isCut(end))
            continue;
        std::string candidate = std::string(text.substr(0, end)) + "\u2026";
        if (!fits(candidate))
            break; // widths only grow with the text
        best = std::move(candidate);
    }
    return best;
}

namespace
{
std::vector<DrawnText>* g_drawnTextSink = nullptr;
TextKind g_textKind = TextKind::Interface;
} // namespace

const char* textKindName(TextKind kind)
{
    switch (kind)
    {
    case TextKind::Interface:
        return "interface";
    case TextKind::Hud:
        return "hud";
    case TextKind::Hint:
        return "hint";
    case TextKind::Physics:
        return "physics";
    case TextKind::Formula:
        return "formula";
    }
    return "interface";
}

TextKindScope::TextKindScope(TextKind kind) : m_previous(g_textKind)
{
    g_textKind = kind;
}

TextKindScope::~TextKindScope()
{
    g_textKind = m_previous;
}

void setDrawnTextSink(std::vector<DrawnText>* sink)
{
    g_drawnTextSink = sink;
}

sf::FloatRect drawLabel(sf::RenderTarget& target, const sf::Font& font, const sf::String& text, sf::Vector2f position,
                        unsigned size, sf::Color colour, Align align)
{
    if (g_drawnTextSink != nullptr)
    {
        const std::basic_string<sf::Uint8> utf8Text = text.toUtf8();
        g_drawnTextSink->push_back({std::string(utf8Text.begin(), utf8Text.end()), g_textKind});
    }
    // One layout pass: the glyphs and their pens, and the width the alignment needs.
    struct PlacedGlyph
    {
        const sf::Glyph* glyph;
        sf::Vector2f pen;
    };
    static std::vector<PlacedGlyph> placed;
    placed.clear();
    const float width = layoutGlyphs(font, text, size,
                                     [](const sf::Glyph& glyph, sf::Vector2f pen) {
                                         placed.push_back({&glyph, pen});
                                     });
    if (align == Align::Centre)
        position.x -= 0.5f * width;
    else if (align == Align::Right)
        position.x -= width;
    // Whole pixels keep glyphs sharp.
    position = {std::round(position.x), std::round(position.y)};
    if (!drawingPixels())
        return {position, {width, FontMetrics::of(font).lineSpacing(size)}};

    // The shadow and the text in one batch and one draw call, every shadow first (below every glyph).
    static std::vector<sf::Vertex> vertices;
    vertices.clear();
    const float shadowOffset = std::max(1.0f, static_cast<float>(size) / 14.0f);
    const sf::Vector2f shadowAt = position + sf::Vector2f(shadowOffset, shadowOffset);
    const sf::Color shadow(0, 0, 0, static_cast<sf::Uint8>(colour.a * 0.55f));
    for (const PlacedGlyph& g : placed)
        appendGlyphQuad(vertices, shadowAt + g.pen, *g.glyph, shadow);
    for (const PlacedGlyph& g : placed)
        appendGlyphQuad(vertices, position + g.pen, *g.glyph, colour);
    if (!vertices.empty())
    {
        sf::RenderStates states;
        states.texture = &font.getTexture(size); // after the layout: new glyphs may have grown the texture
        target.draw(vertices.data(), vertices.size(), sf::Triangles, states);
    }
    return {position, {width, FontMetrics::of(font).lineSpacing(size)}};
}

} // namespace abalike::app
