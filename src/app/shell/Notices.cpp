#include "shell/Notices.hpp"

#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "render/ScreenRegions.hpp"
#include "shell/Trace.hpp"
#include "shell/UiMetrics.hpp"

#include <SFML/Graphics/RectangleShape.hpp>
#include <abalike/save/SaveStore.hpp>
#include <algorithm>
#include <iostream>

namespace abalike::app
{

namespace
{
constexpr double kNoticeS = 6.0;
constexpr std::size_t kMaxNotices = 4;
} // namespace

void Notices::notify(const std::string& message)
{
    notify(message, "");
}

void Notices::notify(const std::string& message, const std::string& topic)
{
    std::cerr << "abalike: " << message << '\n';
    m_trace.write("notice", {{"text", message}});
    if (!topic.empty())
        std::erase_if(m_notices, [&topic](const Notice& notice) { return notice.topic == topic; });
    m_notices.push_back({message, 0.0, topic});
    if (m_notices.size() > kMaxNotices)
        m_notices.erase(m_notices.begin());
}

void Notices::takeMessagesOf(SaveStore& store)
{
    for (const std::string& message : store.takeMessages())
        notify(message);
}

void Notices::age(double frameS)
{
    for (Notice& notice : m_notices)
        notice.shownS += frameS;
    std::erase_if(m_notices, [](const Notice& n) { return n.shownS > kNoticeS; });
}

void Notices::draw(sf::RenderTarget& target, const UiMetrics& ui) const
{
    const sf::Font* font = ui.font();
    if (font == nullptr || m_notices.empty())
        return;
    const unsigned size = ui.textSize(17.0f);
    const float pad = 8.0f * ui.scale();
    const float lineHeight = font->getLineSpacing(size);
    const sf::Vector2u window = ui.windowSize();
    const float centre = 0.5f * static_cast<float>(window.x);
    // Each notice wrapped to the window (a long file name must not run off its edges), stacked upwards from above
    // the level's hint.
    const float maxWidth = std::max(100.0f, static_cast<float>(window.x) - 4.0f * pad);
    std::vector<std::vector<std::string>> wrapped;
    std::size_t lines = 0;
    for (const Notice& notice : m_notices)
    {
        wrapped.push_back(wrapText(*font, notice.text, size, maxWidth - 2.0f * pad));
        lines += wrapped.back().size();
    }
    float y = static_cast<float>(window.y) - 70.0f * ui.scale() - lineHeight * static_cast<float>(lines) -
              pad * static_cast<float>(m_notices.size() - 1);
    for (const std::vector<std::string>& notice : wrapped)
    {
        float width = 0.0f;
        for (const std::string& line : notice)
            width = std::max(width, measureText(*font, utf8(line), size).x);
        width += 2.0f * pad;
        const float height = lineHeight * static_cast<float>(notice.size()) + pad;
        sf::RectangleShape box({width, height});
        box.setPosition(centre - 0.5f * width, y - 0.5f * pad);
        recordScreenRegion("notice", {box.getPosition(), box.getSize()});
        box.setFillColor(palette::kPanel);
        target.draw(box);
        for (const std::string& line : notice)
        {
            drawLabel(target, *font, utf8(line), {centre, y}, size, palette::kText, Align::Centre);
            y += lineHeight;
        }
        y += pad;
    }
}

} // namespace abalike::app
