#include "teach/Guide.hpp"

#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "render/ScreenRegions.hpp"
#include "teach/TeachDraw.hpp"

#include <algorithm>

namespace abalike::app
{

void GuideRunner::start(Guide guide)
{
    m_guide = std::move(guide);
    m_step = 0;
    m_shotsAtStepStart = 0;
    m_firstAim.reset();
}

void GuideRunner::update(GuideContext context)
{
    if (!m_guide || context.session == nullptr)
        return;
    if (!m_firstAim && context.aim)
        m_firstAim = context.aim;
    context.firstAim = m_firstAim;
    while (m_step < m_guide->steps.size())
    {
        context.shotsAtStepStart = m_shotsAtStepStart;
        if (!m_guide->steps[m_step].done(context))
            break;
        ++m_step;
        m_shotsAtStepStart = context.shots();
    }
}

sf::FloatRect GuideRunner::draw(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topLeft, float maxWidth,
                                unsigned titleSize, unsigned rowSize, float scale) const
{
    if (!m_guide)
        return {};
    const bool finished = m_step >= m_guide->steps.size();
    const std::string& text = finished ? m_guide->closing : m_guide->steps[m_step].text;
    const std::string progress =
        finished ? "done" : "step " + std::to_string(m_step + 1) + " of " + std::to_string(m_guide->steps.size());
    const float pad = 10.0f * scale;
    std::vector<std::string> lines = wrapText(font, text, rowSize, maxWidth - 2.0f * pad);
    const float rowHeight = font.getLineSpacing(rowSize);
    const float titleHeight = font.getLineSpacing(titleSize) * 1.15f;
    const auto cardWith = [&](std::size_t rows)
    {
        return sf::FloatRect(topLeft, {maxWidth, 2.0f * pad + titleHeight + rowHeight * static_cast<float>(rows)});
    };
    // In a window too small for the whole step (large text, a low window) the card keeps as many lines as have room
    // above the panels under it, filled with its first whole sentences; with no room even for its title it is left out.
    std::size_t rows = std::min(lines.size(), shrunkRows("guide").value_or(lines.size()));
    while (rows > 0 && !panelHasRoom(target, cardWith(rows)))
        --rows;
    // Nor does it cover the slingshot, the flying bird or a live pig: it gives up lines instead, and keeps to that
    // many until the next aim, so that it does not grow and shrink as the bird flies past.
    while (rows > 0 && coversKeptInView(cardWith(rows)))
        markPanelShrunk("guide", --rows);
    // Its title alone still would (the bird flies past, a pig sits high): left out while it does.
    if (!panelHasRoom(target, cardWith(rows)) || coversKeptInView(cardWith(rows)))
        return {};
    if (rows < lines.size())
    {
        // Its first whole sentences that fit: never a sentence cut short.
        lines = wrapWholeSentences(font, text, rowSize, maxWidth - 2.0f * pad, rows);
        rows = lines.size();
    }
    const sf::FloatRect rect = cardWith(rows);
    drawTeachPanel(target, rect, scale, "guide");
    drawLabel(target, font, utf8(m_guide->title), {rect.left + pad, rect.top + pad}, titleSize, palette::kStar);
    drawLabel(target, font, utf8(progress), {rect.left + rect.width - pad, rect.top + pad}, rowSize, palette::kTextDim,
              Align::Right);
    float y = rect.top + pad + titleHeight;
    for (const std::string& line : lines)
    {
        drawLabel(target, font, utf8(line), {rect.left + pad, y}, rowSize, palette::kText);
        y += rowHeight;
    }
    return rect;
}

} // namespace abalike::app
