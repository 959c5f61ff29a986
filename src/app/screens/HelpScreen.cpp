#include "screens/HelpScreen.hpp"

#include "input/Controls.hpp"
#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "screens/App.hpp"
#include "ui/Card.hpp"

#include <algorithm>

namespace abalike::app
{

void HelpScreen::handleEvent(const sf::Event& event)
{
    // F1 and '?' are the app's (they toggle this screen); anything else that is a deliberate input closes it.
    const bool key = event.type == sf::Event::KeyPressed && event.key.code != sf::Keyboard::F1 &&
                     event.key.code != sf::Keyboard::LShift && event.key.code != sf::Keyboard::RShift;
    const bool click = event.type == sf::Event::MouseButtonReleased;
    if (key || click)
        m_app.screens().pop();
}

void HelpScreen::draw(sf::RenderTarget& target)
{
    drawScrim(target);
    const sf::Font* font = m_app.font();
    if (font == nullptr)
        return;
    const float scale = m_app.uiScale();
    const sf::Vector2f window(target.getSize());
    const unsigned titleSize = m_app.textSize(30.0f);
    const unsigned headSize = m_app.textSize(17.0f);
    const unsigned rowSize = m_app.textSize(16.0f);
    const float rowHeight = font->getLineSpacing(rowSize);
    const std::vector<ControlBinding>& table = controlTable();

    // Three columns sized to their widest entry.
    float actionWidth = 0.0f;
    float keysWidth = 0.0f;
    float mouseWidth = 0.0f;
    int groups = 0;
    std::string lastGroup;
    for (const ControlBinding& row : table)
    {
        actionWidth = std::max(actionWidth, measureText(*font, utf8(row.action), rowSize).x);
        keysWidth = std::max(keysWidth, measureText(*font, utf8(row.keys), rowSize).x);
        mouseWidth = std::max(mouseWidth, measureText(*font, utf8(row.mouse), rowSize).x);
        if (row.where != lastGroup)
            ++groups;
        lastGroup = row.where;
    }
    const float gap = 28.0f * scale;
    const float pad = 24.0f * scale;
    const float width = std::min(window.x - 20.0f, actionWidth + keysWidth + mouseWidth + 2.0f * gap + 2.0f * pad);
    const float height = font->getLineSpacing(titleSize) + rowHeight * 1.4f +
                         static_cast<float>(table.size()) * rowHeight +
                         static_cast<float>(groups) * font->getLineSpacing(headSize) * 1.3f + 2.0f * pad + rowHeight;
    const sf::FloatRect card(0.5f * (window.x - width), std::max(10.0f, 0.5f * (window.y - height)), width, height);
    drawCard(target, card, scale, palette::kButtonOutline);

    float y = card.top + pad;
    drawLabel(target, *font, utf8("Controls"), {card.left + 0.5f * width, y}, titleSize, palette::kText, Align::Centre);
    y += font->getLineSpacing(titleSize);
    const float actionX = card.left + pad;
    const float keysX = actionX + actionWidth + gap;
    const float mouseX = keysX + keysWidth + gap;
    drawLabel(target, *font, utf8("Keyboard"), {keysX, y}, headSize, palette::kStar);
    drawLabel(target, *font, utf8("Mouse"), {mouseX, y}, headSize, palette::kStar);
    y += rowHeight * 1.4f;
    lastGroup.clear();
    for (const ControlBinding& row : table)
    {
        if (row.where != lastGroup)
        {
            drawLabel(target, *font, utf8(row.where), {actionX, y}, headSize, palette::kStar);
            y += font->getLineSpacing(headSize) * 1.3f;
            lastGroup = row.where;
        }
        drawLabel(target, *font, utf8(row.action), {actionX, y}, rowSize, palette::kText);
        drawLabel(target, *font, utf8(row.keys), {keysX, y}, rowSize, palette::kText);
        drawLabel(target, *font, utf8(row.mouse.empty() ? "\u2014" : row.mouse), {mouseX, y}, rowSize,
                  palette::kTextDim);
        y += rowHeight;
    }
    drawLabel(target, *font, utf8("Press any key or click to close"), {card.left + 0.5f * width, y + 0.3f * rowHeight},
              rowSize, palette::kTextDim, Align::Centre);
}

} // namespace abalike::app
