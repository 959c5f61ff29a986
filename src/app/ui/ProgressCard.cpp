#include "ui/ProgressCard.hpp"

#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "ui/Card.hpp"

#include <SFML/Graphics/RectangleShape.hpp>
#include <algorithm>
#include <string>
#include <vector>

namespace abalike::app
{

void drawProgressCard(sf::RenderTarget& target, const sf::Font* font, const Progress& progress, unsigned titleSize,
                      unsigned detailSize, float scale)
{
    const sf::Vector2f window(target.getSize());
    target.clear(palette::kSkyBottom);
    const float width = std::min(window.x - 40.0f * scale, 560.0f * scale);
    const float pad = 18.0f * scale;
    const float inner = width - 2.0f * pad;
    const float barHeight = 16.0f * scale;
    const float gap = 12.0f * scale;
    // Long titles and details wrap inside the card rather than run past it.
    std::vector<std::string> titleLines;
    std::vector<std::string> detailLines;
    float textHeight = 0.0f;
    if (font != nullptr)
    {
        titleLines = wrapText(*font, progress.title, titleSize, inner);
        detailLines = wrapText(*font, progress.detail, detailSize, inner);
        textHeight = font->getLineSpacing(titleSize) * static_cast<float>(titleLines.size()) +
                     font->getLineSpacing(detailSize) * static_cast<float>(detailLines.size());
    }
    const float height = 2.0f * pad + textHeight + gap + barHeight;
    const sf::FloatRect card(0.5f * (window.x - width), 0.5f * (window.y - height), width, height);
    drawCard(target, card, scale, palette::kButtonOutline);

    float y = card.top + pad;
    if (font != nullptr)
    {
        for (const std::string& line : titleLines)
        {
            drawLabel(target, *font, utf8(line), {card.left + pad, y}, titleSize, palette::kText);
            y += font->getLineSpacing(titleSize);
        }
        for (const std::string& line : detailLines)
        {
            drawLabel(target, *font, utf8(line), {card.left + pad, y}, detailSize, palette::kTextDim);
            y += font->getLineSpacing(detailSize);
        }
    }
    y += gap;
    sf::RectangleShape track({inner, barHeight});
    track.setPosition(card.left + pad, y);
    track.setFillColor(palette::kButton);
    track.setOutlineColor(palette::kButtonOutline);
    track.setOutlineThickness(std::max(1.0f, scale));
    target.draw(track);
    sf::RectangleShape done({inner * std::clamp(progress.fraction, 0.0f, 1.0f), barHeight});
    done.setPosition(card.left + pad, y);
    done.setFillColor(palette::kStar);
    target.draw(done);
}

} // namespace abalike::app
