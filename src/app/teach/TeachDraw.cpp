#include "teach/TeachDraw.hpp"

#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "render/ScreenRegions.hpp"
#include "render/TextFormat.hpp"

#include <SFML/Graphics/RectangleShape.hpp>
#include <algorithm>
#include <cmath>

namespace abalike::app
{

void addArrow(Mesh& mesh, sf::Vector2f from, sf::Vector2f to, float width, sf::Color colour, float rim)
{
    const sf::Vector2f d = to - from;
    const float length = std::hypot(d.x, d.y);
    if (length < 1.0f)
        return;
    const sf::Vector2f u = d / length;
    const sf::Vector2f n(-u.y, u.x);
    // The head never takes more than half the arrow, so short arrows still show their shaft.
    const float head = std::min(3.2f * width + 4.0f, 0.5f * length);
    const sf::Vector2f base = to - head * u;
    const float half = 0.55f * head + 0.5f * width;
    if (rim > 0.0f)
    {
        const sf::Color dark(20, 24, 36, 210);
        mesh.addLine(from - rim * u, base, width + 2.0f * rim, dark);
        mesh.addTriangle(to + 2.0f * rim * u, base - rim * u + (half + 1.8f * rim) * n,
                         base - rim * u - (half + 1.8f * rim) * n, dark);
    }
    mesh.addLine(from, base, width, colour);
    mesh.addTriangle(to, base + half * n, base - half * n, colour);
}

void drawTeachPanel(sf::RenderTarget& target, sf::FloatRect rect, float scale, std::string_view name)
{
    recordScreenRegion(name, rect);
    sf::RectangleShape box({rect.width, rect.height});
    box.setPosition(rect.left, rect.top);
    box.setFillColor(teach::kPanel);
    box.setOutlineColor(teach::kPanelEdge);
    box.setOutlineThickness(std::max(1.0f, scale));
    target.draw(box);
}

bool panelHasRoom(const sf::RenderTarget& target, const sf::FloatRect& rect)
{
    const sf::Vector2f window(target.getSize());
    if (rect.left < 0.0f || rect.top < 0.0f || rect.left + rect.width > window.x || rect.top + rect.height > window.y)
        return false;
    sf::FloatRect overlap;
    for (const ScreenRegion& region : screenLayout())
        if (rect.intersects(region.rect, overlap) && overlap.width > 0.0f && overlap.height > 0.0f)
            return false;
    return true;
}

bool fullPanelFits(const sf::RenderTarget& target, const sf::FloatRect& rect, std::string_view name)
{
    if (panelShrunk(name) || !panelHasRoom(target, rect))
        return false;
    if (coversKeptInView(rect))
    {
        markPanelShrunk(name);
        return false;
    }
    return true;
}

bool coversKeptInView(const sf::FloatRect& rect, bool flyingBird, bool slingshot)
{
    sf::FloatRect overlap;
    for (const ScreenRegion& thing : keepInView())
        if ((flyingBird || thing.name != "bird") && (slingshot || thing.name != "slingshot") &&
            rect.intersects(thing.rect, overlap) && overlap.width > 0.0f && overlap.height > 0.0f)
            return true;
    return false;
}

sf::FloatRect drawPanelSummary(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f corner, bool fromRight,
                               const std::string& text, unsigned rowSize, float scale, std::string_view name)
{
    const float pad = 8.0f * scale;
    const float room =
        fromRight ? corner.x - 2.0f * pad : static_cast<float>(target.getSize().x) - corner.x - 2.0f * pad;
    const std::string line = fitToWidth(font, text, rowSize, room, Cut::AtWord);
    if (line.empty())
        return {};
    const sf::Vector2f size(measureText(font, utf8(line), rowSize).x + 2.0f * pad,
                            font.getLineSpacing(rowSize) + 2.0f * pad);
    const sf::FloatRect rect({fromRight ? corner.x - size.x : corner.x, corner.y}, size);
    if (!panelHasRoom(target, rect))
        return {};
    // A summary that would cover the slingshot, the landing point or a live pig is left out, until the next aim; one
    // the flying bird passes under, while it does.
    const std::string hidden = std::string(name) + " (summary left out)";
    if (panelShrunk(hidden))
        return {};
    if (coversKeptInView(rect, false))
    {
        markPanelShrunk(hidden);
        return {};
    }
    if (coversKeptInView(rect))
        return {};
    drawTeachPanel(target, rect, scale, name);
    drawLabel(target, font, utf8(line), {rect.left + pad, rect.top + pad}, rowSize, palette::kText);
    return rect;
}

namespace
{
struct PanelMetrics
{
    float pad = 0.0f;
    float swatch = 0.0f;
    float labelWidth = 0.0f;
    float valueWidth = 0.0f;
    float gap = 0.0f;
    float titleHeight = 0.0f;
    float rowHeight = 0.0f;
};
} // namespace

sf::Vector2f TextPanel::measure(const sf::Font& font, unsigned titleSize, unsigned rowSize, float scale) const
{
    PanelMetrics m;
    m.pad = 8.0f * scale;
    m.swatch = 12.0f * scale;
    m.gap = 14.0f * scale;
    m.titleHeight = m_title.empty() ? 0.0f : font.getLineSpacing(titleSize) * 1.1f;
    m.rowHeight = font.getLineSpacing(rowSize);
    float width = m_title.empty() ? 0.0f : measureText(font, utf8(m_title), titleSize).x;
    for (const PanelRow& row : m_rows)
    {
        const float label = measureText(font, utf8(row.label), rowSize).x + (row.swatch.a > 0 ? m.swatch * 1.6f : 0.0f);
        if (row.heading || row.value.empty())
            width = std::max(width, label);
        else
        {
            m.labelWidth = std::max(m.labelWidth, label);
            m.valueWidth = std::max(m.valueWidth, measureText(font, utf8(row.value), rowSize).x);
        }
    }
    width = std::max(width, m.labelWidth + m.gap + m.valueWidth);
    return {width + 2.0f * m.pad, m.titleHeight + m.rowHeight * static_cast<float>(m_rows.size()) + 2.0f * m.pad};
}

sf::FloatRect TextPanel::draw(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f at, unsigned titleSize,
                              unsigned rowSize, float scale) const
{
    const sf::Vector2f size = measure(font, titleSize, rowSize, scale);
    const sf::FloatRect rect(at, size);
    drawTeachPanel(target, rect, scale, m_title);
    const float pad = 8.0f * scale;
    const float swatch = 12.0f * scale;
    float y = at.y + pad;
    if (!m_title.empty())
    {
        drawLabel(target, font, utf8(m_title), {at.x + pad, y}, titleSize, palette::kStar);
        y += font.getLineSpacing(titleSize) * 1.1f;
    }
    const float rowHeight = font.getLineSpacing(rowSize);
    Mesh swatches;
    for (const PanelRow& row : m_rows)
    {
        float x = at.x + pad;
        if (row.swatch.a > 0)
        {
            const float top = y + 0.5f * (rowHeight - swatch);
            swatches.addConvex(
                std::vector<sf::Vector2f>{{x, top}, {x + swatch, top}, {x + swatch, top + swatch}, {x, top + swatch}},
                row.swatch);
            x += swatch * 1.6f;
        }
        drawLabel(target, font, utf8(row.label), {x, y}, rowSize, row.heading ? palette::kStar : palette::kTextDim);
        if (!row.heading && !row.value.empty())
            drawLabel(target, font, utf8(row.value), {at.x + size.x - pad, y}, rowSize, palette::kText, Align::Right);
        y += rowHeight;
    }
    swatches.draw(target);
    return rect;
}

void LabelPlacer::draw(sf::RenderTarget& target, const sf::Font& font, const std::string& text, sf::Vector2f at,
                       bool alignRight, unsigned size, sf::Color colour)
{
    const float lineHeight = font.getLineSpacing(size);
    const float width = measureText(font, utf8(text), size).x;
    const sf::FloatRect first(alignRight ? at.x - width : at.x, at.y - 0.5f * lineHeight, width, lineHeight);
    sf::FloatRect box = first;
    for (const float shift : {0.0f, 1.0f, -1.0f, 2.0f, -2.0f})
    {
        box = first;
        box.top += shift * lineHeight;
        if (std::none_of(m_placed.begin(), m_placed.end(),
                         [&](const sf::FloatRect& other) { return other.intersects(box); }))
            break;
    }
    m_placed.push_back(box);
    // Over the open sky a coloured word can be unreadable: white text on a dark chip, the colour as a bar beside it.
    const float bar = std::max(3.0f, 0.25f * static_cast<float>(size));
    sf::RectangleShape chip({box.width + 1.5f * bar, box.height});
    chip.setPosition(box.left - 1.5f * bar, box.top);
    chip.setFillColor(teach::kPanel);
    target.draw(chip);
    sf::RectangleShape swatch({bar, box.height});
    swatch.setPosition(box.left - 1.5f * bar, box.top);
    swatch.setFillColor(colour);
    target.draw(swatch);
    drawLabel(target, font, utf8(text), {box.left + 0.25f * bar, box.top}, size, palette::kText);
}

std::string withUnit(double value, int decimals, const char* unit)
{
    return formatFixed(value, decimals) + " " + unit;
}

} // namespace abalike::app
