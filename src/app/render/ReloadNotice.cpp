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
constexpr std::size_t kMaxLines = 8;
const sf::Color kNoticePanel(90, 16, 16, 220);
const sf::Color kNoticeTitle(255, 214, 200);
} // namespace

void ReloadNotice::draw(sf::RenderTarget& target, sf::Vector2u size, const std::vector<std::string>& lines,
                        float textScale, const std::string& heading) const
{
    if (m_font == nullptr || lines.empty())
        return;
    const float scale = hudScale(size) * textScale;
    const auto titleSize = static_cast<unsigned>(std::round(17.0f * scale));
    const auto lineSize = static_cast<unsigned>(std::round(14.0f * scale));
    const float pad = 10.0f * scale;
    const std::size_t shown = std::min(lines.size(), kMaxLines);
    const bool more = lines.size() > shown;
    const float height = 2 * pad + m_font->getLineSpacing(titleSize) +
                         static_cast<float>(shown + (more ? 1 : 0)) * m_font->getLineSpacing(lineSize);
    const float top = static_cast<float>(size.y) - height - 60.0f * scale;

    sf::RectangleShape box({static_cast<float>(size.x) - 2 * pad, height});
    box.setPosition(pad, top);
    recordScreenRegion("reload banner", {{pad, top}, box.getSize()});
    box.setFillColor(kNoticePanel);
    target.draw(box);

    float y = top + pad;
    drawLabel(target, *m_font, utf8(heading), {2 * pad, y}, titleSize, kNoticeTitle);
    y += m_font->getLineSpacing(titleSize);
    for (std::size_t i = 0; i < shown; ++i)
    {
        drawLabel(target, *m_font, utf8(lines[i]), {2 * pad, y}, lineSize, palette::kText);
        y += m_font->getLineSpacing(lineSize);
    }
    if (more)
        drawLabel(target, *m_font, utf8("... and " + std::to_string(lines.size() - shown) + " more (see the terminal)"),
                  {2 * pad, y}, lineSize, palette::kTextDim);
}

} // namespace abalike::app
