#include "render/Label.hpp"

#include <SFML/Graphics/Text.hpp>
#include <algorithm>
#include <cmath>

namespace abalike::app
{

sf::String utf8(std::string_view text)
{
    return sf::String::fromUtf8(text.begin(), text.end());
}

sf::Vector2f measureText(const sf::Font& font, const sf::String& text, unsigned size)
{
    const sf::Text label(text, font, size);
    const sf::FloatRect bounds = label.getLocalBounds();
    return {bounds.left + bounds.width, font.getLineSpacing(size)};
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

namespace
{
std::vector<std::string>* g_drawnTextSink = nullptr;
} // namespace

void setDrawnTextSink(std::vector<std::string>* sink)
{
    g_drawnTextSink = sink;
}

sf::FloatRect drawLabel(sf::RenderTarget& target, const sf::Font& font, const sf::String& text, sf::Vector2f position,
                        unsigned size, sf::Color colour, Align align)
{
    if (g_drawnTextSink != nullptr)
    {
        const std::basic_string<sf::Uint8> utf8Text = text.toUtf8();
        g_drawnTextSink->emplace_back(utf8Text.begin(), utf8Text.end());
    }
    sf::Text label(text, font, size);
    const float width = measureText(font, text, size).x;
    if (align == Align::Centre)
        position.x -= 0.5f * width;
    else if (align == Align::Right)
        position.x -= width;
    // Whole pixels keep glyphs sharp.
    position = {std::round(position.x), std::round(position.y)};

    const float shadowOffset = std::max(1.0f, static_cast<float>(size) / 14.0f);
    label.setFillColor(sf::Color(0, 0, 0, static_cast<sf::Uint8>(colour.a * 0.55f)));
    label.setPosition(position + sf::Vector2f(shadowOffset, shadowOffset));
    target.draw(label);
    label.setFillColor(colour);
    label.setPosition(position);
    target.draw(label);
    return {position, {width, font.getLineSpacing(size)}};
}

} // namespace abalike::app
