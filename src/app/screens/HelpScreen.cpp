#include "screens/HelpScreen.hpp"

#include "input/Controls.hpp"
#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "shell/AppContext.hpp"
#include "shell/Navigator.hpp"
#include "shell/PlayerSettings.hpp"
#include "shell/UiMetrics.hpp"
#include "ui/Card.hpp"

#include <algorithm>

namespace abalike::app
{

namespace
{
constexpr float kTitleNominal = 30.0f;
constexpr float kHeadNominal = 17.0f;
constexpr float kRowNominal = 16.0f;

std::string orDash(const std::string& text)
{
    return text.empty() ? "\u2014" : text;
}

/// The stacked form's second line: every way to do the action.
std::string waysLine(const ControlBinding& row)
{
    return "keys: " + orDash(row.keys) + "   mouse: " + orDash(row.mouse) + "   pad: " + orDash(row.gamepad);
}
} // namespace

void HelpScreen::turnPage(int delta)
{
    m_page = std::clamp(m_page + delta, 0, m_pages - 1);
}

void HelpScreen::close()
{
    if (m_closing)
        return;
    m_closing = true;
    m_app.navigator().screens().pop();
}

void HelpScreen::handleEvent(const sf::Event& event)
{
    // F1 and the text '?' close it at once; page keys turn pages; any other deliberate key closes it when it is let
    // go (the key press of a '?' comes before its text).
    if (m_closing)
        return;
    if (event.type == sf::Event::TextEntered)
    {
        if (event.text.unicode == '?')
            close();
    }
    else if (event.type == sf::Event::KeyReleased)
    {
        if (m_pressed.count(event.key.code) != 0)
            close();
    }
    else if (event.type == sf::Event::KeyPressed)
    {
        switch (event.key.code)
        {
        case sf::Keyboard::F1:
            close();
            return;
        case sf::Keyboard::LShift:
        case sf::Keyboard::RShift:
            return;
        case sf::Keyboard::Right:
        case sf::Keyboard::Tab:
        case sf::Keyboard::PageDown:
            if (m_page + 1 < m_pages)
            {
                turnPage(+1);
                return;
            }
            break;
        case sf::Keyboard::Left:
        case sf::Keyboard::PageUp:
            if (m_page > 0)
            {
                turnPage(-1);
                return;
            }
            break;
        default:
            break;
        }
        m_pressed.insert(event.key.code);
    }
    else if (event.type == sf::Event::MouseButtonReleased)
    {
        if (m_page + 1 < m_pages)
            turnPage(+1);
        else
            close();
    }
}

std::vector<std::vector<HelpScreen::Line>> HelpScreen::paginate(const sf::Font& font, float usableHeight,
                                                                const std::vector<float>& rowHeights) const
{
    const float headHeight = font.getLineSpacing(m_app.ui().textSize(kHeadNominal)) * 1.3f;
    // School wording leaves out the integrator tools, as the toolbar does.
    std::vector<ControlBinding> table;
    for (const ControlBinding& row : controlTable())
        if (m_app.settings().universityWording() ||
            (row.action.find("RK4") == std::string::npos && row.action.find("Integrator") == std::string::npos))
            table.push_back(row);
    std::vector<std::vector<Line>> pages(1);
    float used = 0.0f;
    for (std::size_t i = 0; i < table.size(); ++i)
    {
        const bool newGroup = i == 0 || table[i].where != table[i - 1].where;
        const float lineHeight = rowHeights[i];
        const float need = lineHeight + (newGroup ? headHeight : 0.0f);
        if (used + need > usableHeight && !pages.back().empty())
        {
            pages.emplace_back();
            used = 0.0f;
        }
        // A group continued on a new page repeats its heading.
        if (newGroup || pages.back().empty())
        {
            pages.back().push_back({i, true, headHeight});
            used += headHeight;
        }
        pages.back().push_back({i, false, lineHeight});
        used += lineHeight;
    }
    return pages;
}

void HelpScreen::draw(sf::RenderTarget& target)
{
    drawScrim(target);
    const sf::Font* font = m_app.ui().font();
    if (font == nullptr)
        return;
    const float scale = m_app.ui().scale();
    const sf::Vector2f window(target.getSize());
    const unsigned titleSize = m_app.ui().textSize(kTitleNominal);
    const unsigned headSize = m_app.ui().textSize(kHeadNominal);
    const unsigned rowSize = m_app.ui().textSize(kRowNominal);
    const float rowHeight = font->getLineSpacing(rowSize);
    // School wording leaves out the integrator tools, as the toolbar does.
    std::vector<ControlBinding> table;
    for (const ControlBinding& row : controlTable())
        if (m_app.settings().universityWording() ||
            (row.action.find("RK4") == std::string::npos && row.action.find("Integrator") == std::string::npos))
            table.push_back(row);

    // Four columns sized to their widest entry, if they fit; otherwise each control takes two lines.
    float actionWidth = 0.0f;
    float keysWidth = 0.0f;
    float mouseWidth = 0.0f;
    float padWidth = 0.0f;
    float stackedWidth = 0.0f;
    for (const ControlBinding& row : table)
    {
        actionWidth = std::max(actionWidth, measureText(*font, utf8(row.action), rowSize).x);
        keysWidth = std::max(keysWidth, measureText(*font, utf8(orDash(row.keys)), rowSize).x);
        mouseWidth = std::max(mouseWidth, measureText(*font, utf8(orDash(row.mouse)), rowSize).x);
        padWidth = std::max(padWidth, measureText(*font, utf8(orDash(row.gamepad)), rowSize).x);
        stackedWidth = std::max({stackedWidth, measureText(*font, utf8(row.action), rowSize).x + 16.0f * scale,
                                 measureText(*font, utf8(waysLine(row)), rowSize).x});
    }
    const float gap = 24.0f * scale;
    const float pad = 20.0f * scale;
    const float maxWidth = window.x - 20.0f;
    const float columnsWidth = actionWidth + keysWidth + mouseWidth + padWidth + 3.0f * gap + 2.0f * pad;
    const bool stacked = columnsWidth > maxWidth;
    const float width = std::min(maxWidth, stacked ? stackedWidth + 2.0f * pad : columnsWidth);

    const float chrome =
        font->getLineSpacing(titleSize) + (stacked ? 0.0f : rowHeight * 1.4f) + 2.0f * pad + 1.5f * rowHeight;
    // Stacked: the action, then every way to do it, wrapped to the card.
    std::vector<std::vector<std::string>> ways(table.size());
    std::vector<float> rowHeights(table.size(), rowHeight);
    for (std::size_t i = 0; stacked && i < table.size(); ++i)
    {
        ways[i] = wrapText(*font, waysLine(table[i]), rowSize, width - 2.0f * pad - 16.0f * scale);
        rowHeights[i] = (1.25f + static_cast<float>(ways[i].size())) * rowHeight;
    }
    const std::vector<std::vector<Line>> pages = paginate(*font, window.y - 20.0f - chrome, rowHeights);
    m_pages = static_cast<int>(pages.size());
    m_page = std::min(m_page, m_pages - 1);
    const std::vector<Line>& page = pages[static_cast<std::size_t>(m_page)];
    float linesHeight = 0.0f;
    for (const Line& line : page)
        linesHeight += line.height;
    const float height = chrome + linesHeight;
    const sf::FloatRect card(0.5f * (window.x - width), std::max(10.0f, 0.5f * (window.y - height)), width, height);
    drawCard(target, card, scale, palette::kButtonOutline);

    float y = card.top + pad;
    drawLabel(target, *font, utf8("Controls"), {card.left + 0.5f * width, y}, titleSize, palette::kText, Align::Centre);
    y += font->getLineSpacing(titleSize);
    const float actionX = card.left + pad;
    const float keysX = actionX + actionWidth + gap;
    const float mouseX = keysX + keysWidth + gap;
    const float padX = mouseX + mouseWidth + gap;
    if (!stacked)
    {
        drawLabel(target, *font, utf8("Keyboard"), {keysX, y}, headSize, palette::kStar);
        drawLabel(target, *font, utf8("Mouse"), {mouseX, y}, headSize, palette::kStar);
        drawLabel(target, *font, utf8("Gamepad"), {padX, y}, headSize, palette::kStar);
        y += rowHeight * 1.4f;
    }
    for (const Line& line : page)
    {
        const ControlBinding& row = table[line.row];
        if (line.heading)
            drawLabel(target, *font, utf8(row.where), {actionX, y}, headSize, palette::kStar);
        else if (stacked)
        {
            drawLabel(target, *font, utf8(row.action), {actionX, y}, rowSize, palette::kText);
            float wayY = y + rowHeight;
            for (const std::string& way : ways[line.row])
            {
                drawLabel(target, *font, utf8(way), {actionX + 16.0f * scale, wayY}, rowSize, palette::kTextDim);
                wayY += rowHeight;
            }
        }
        else
        {
            drawLabel(target, *font, utf8(row.action), {actionX, y}, rowSize, palette::kText);
            drawLabel(target, *font, utf8(orDash(row.keys)), {keysX, y}, rowSize, palette::kText);
            drawLabel(target, *font, utf8(orDash(row.mouse)), {mouseX, y}, rowSize, palette::kTextDim);
            drawLabel(target, *font, utf8(orDash(row.gamepad)), {padX, y}, rowSize, palette::kTextDim);
        }
        y += line.height;
    }
    std::string footer = "Press any key or click to close";
    if (m_page + 1 < m_pages)
        footer = "Page " + std::to_string(m_page + 1) + " of " + std::to_string(m_pages) +
                 ": \u2192, Tab or a click for more; any other key closes";
    else if (m_pages > 1)
        footer = "Page " + std::to_string(m_pages) + " of " + std::to_string(m_pages) +
                 ": \u2190 goes back; any other key or a click closes";
    drawLabel(target, *font, utf8(footer), {card.left + 0.5f * width, y + 0.3f * rowHeight}, rowSize, palette::kTextDim,
              Align::Centre);
}

} // namespace abalike::app
