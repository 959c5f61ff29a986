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

ReloadNotice::Layout ReloadNotice::layout(sf::Vector2u size, const std::vector<std::string>& lines, float textScale,
                                          const std::string& heading) const
{
    Layout out;
    const float scale = hudScale(size) * textScale;
    out.titleSize = static_cast<unsigned>(std::round(17.0f * scale));
    out.lineSize = static_cast<unsigned>(std::round(14.0f * scale));
    out.pad = 10.0f * scale;
    const float textWidth = static_cast<float>(size.x) - 4 * out.pad;
    const std::string count = std::to_string(lines.size()) + (lines.size() == 1 ? " problem" : " problems");
    // Folded it is one line (the heading and how to open it), so the level stays in view; open, every problem in
    // whole lines, as many as fit in its share of the window.
    out.title = wrapText(*m_font, heading + "  (B: " + (m_expanded ? "fold the " : "read the ") + count + ")",
                         out.titleSize, textWidth);
    if (m_expanded)
    {
        const float room = kMaxOpenShare * static_cast<float>(size.y) -
                           m_font->getLineSpacing(out.titleSize) * static_cast<float>(out.title.size()) - 2 * out.pad;
        // Whole lines that fit, one kept for "and N more".
        const auto fits =
            static_cast<std::size_t>(std::max(1.0f, std::floor(room / m_font->getLineSpacing(out.lineSize))) - 1.0f);
        for (std::size_t i = 0; i < lines.size(); ++i)
        {
            const std::vector<std::string> wrapped = wrapText(*m_font, lines[i], out.lineSize, textWidth);
            if (out.body.size() + wrapped.size() > fits)
            {
                out.hidden = lines.size() - i;
                break;
            }
            out.body.insert(out.body.end(), wrapped.begin(), wrapped.end());
        }
    }
    out.height = 2 * out.pad + m_font->getLineSpacing(out.titleSize) * static_cast<float>(out.title.size()) +
                 static_cast<float>(out.body.size() + (out.hidden > 0 ? 1 : 0)) * m_font->getLineSpacing(out.lineSize);
    out.top = static_cast<float>(size.y) - out.height - 60.0f * scale;
    return out;
}

float ReloadNotice::reach(sf::Vector2u size, const std::vector<std::string>& lines, float textScale,
                          const std::string& heading) const
{
    if (m_font == nullptr || lines.empty())
        return 0.0f;
    return static_cast<float>(size.y) - layout(size, lines, textScale, heading).top;
}

void ReloadNotice::draw(sf::RenderTarget& target, sf::Vector2u size, const std::vector<std::string>& lines,
                        float textScale, const std::string& heading) const
{
    m_lastRect = {};
    if (m_font == nullptr || lines.empty())
        return;
    const Layout l = layout(size, lines, textScale, heading);
    const float pad = l.pad;
    const float top = l.top;
    const float height = l.height;
    const unsigned titleSize = l.titleSize;
    const unsigned lineSize = l.lineSize;
    const std::vector<std::string>& title = l.title;
    const std::vector<std::string>& body = l.body;
    const std::size_t hidden = l.hidden;

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
