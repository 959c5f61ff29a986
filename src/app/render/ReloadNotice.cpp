#include "render/ReloadNotice.hpp"

#include "render/Hud.hpp"
#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "render/ScreenRegions.hpp"

#include <SFML/Graphics/RectangleShape.hpp>
#include <algorithm>
#include <cmath>

namespace abalike::app
{

namespace
{
/// The open banner takes at most this share of the window's height: the level stays in view.
constexpr float kMaxOpenShare = 0.45f;
const sf::Color kNoticePanel(90, 16, 16, 220);
const sf::Color kNoticeTitle(255, 214, 200);
} // namespace

bool ReloadNotice::handleClick(float x, float y)
{
    if (!m_lastRect.contains(x, y))
        return false;
    toggle();
    return true;
}

void ReloadNotice::draw(sf::RenderTarget& target, sf::Vector2u size, const std::vector<std::string>& lines,
                        float textScale, const std::string& heading) const
{
    m_lastRect = {};
    if (m_font == nullptr || lines.empty())
        return;
    const float scale = hudScale(size) * textScale;
    const auto titleSize = static_cast<unsigned>(std::round(17.0f * scale));
    const auto lineSize = static_cast<unsigned>(std::round(14.0f * scale));
    const float pad = 10.0f * scale;
    const float textWidth = static_cast<float>(size.x) - 4 * pad;
    const std::string count = std::to_string(lines.size()) + (lines.size() == 1 ? " problem" : " problems");
    // Folded it is one line (the heading and how to open it), so the level stays in view; open, every problem in
    // whole lines, as many as fit in its share of the window.
    const std::vector<std::string> title = wrapText(
        *m_font, heading + "  (B: " + (m_expanded ? "fold the " : "read the ") + count + ")", titleSize, textWidth);
    std::vector<std::string> body;
    std::size_t hidden = 0;
    if (m_expanded)
    {
        const float room = kMaxOpenShare * static_cast<float>(size.y) -
                           m_font->getLineSpacing(titleSize) * static_cast<float>(title.size()) - 2 * pad;
        // Whole lines that fit, one kept for "and N more".
        const auto fits =
            static_cast<std::size_t>(std::max(1.0f, std::floor(room / m_font->getLineSpacing(lineSize))) - 1.0f);
        for (std::size_t i = 0; i < lines.size(); ++i)
        {
            const std::vector<std::string> wrapped = wrapText(*m_font, lines[i], lineSize, textWidth);
            if (body.size() + wrapped.size() > fits)
            {
                hidden = lines.size() - i;
                break;
            }
            body.insert(body.end(), wrapped.begin(), wrapped.end());
        }
    }
    const float height = 2 * pad + m_font->getLineSpacing(titleSize) * static_cast<float>(title.size()) +
                         static_cast<float>(body.size() + (hidden > 0 ? 1 : 0)) * m_font->getLineSpacing(lineSize);
    const float top = static_cast<float>(size.y) - height - 60.0f * scale;

    sf::RectangleShape box({static_cast<float>(size.x) - 2 * pad, height});
    box.setPosition(pad, top);
    m_lastRect = {{pad, top}, box.getSize()};
    recordScreenRegion("reload banner", m_lastRect);
    box.setFillColor(kNoticePanel);
    target.draw(box);

    float y = top + pad;
    for (const std::string& line : title)
    {
        drawLabel(target, *m_font, utf8(line), {2 * pad, y}, titleSize, kNoticeTitle);
        y += m_font->getLineSpacing(titleSize);
    }
    for (const std::string& line : body)
    {
        drawLabel(target, *m_font, utf8(line), {2 * pad, y}, lineSize, palette::kText);
        y += m_font->getLineSpacing(lineSize);
    }
    if (hidden > 0)
        drawLabel(target, *m_font, utf8("and " + std::to_string(hidden) + " more in the terminal"), {2 * pad, y},
                  lineSize, palette::kTextDim);
}

} // namespace abalike::app
