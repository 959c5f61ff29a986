#include "teach/BirdBodyNotice.hpp"

#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "render/ScreenRegions.hpp"
#include "shell/AppContext.hpp"
#include "shell/Trace.hpp"
#include "shell/UiMetrics.hpp"

#include <SFML/Graphics/RectangleShape.hpp>
#include <abalike/world/BirdBody.hpp>

namespace abalike::app
{

void BirdBodyNotice::frameUpdate(PlayView& view, double frameS)
{
    (void)frameS;
    const GameSession& session = view.session();
    // The bird in the slingshot while aiming; the one in the air while it flies.
    const BirdType* bird = session.currentBird();
    int number = session.birdsUsed();
    if (session.phase() == Phase::Flying && !session.shots().empty())
    {
        bird = session.catalog().findBird(session.shots().back().bird);
        number = session.birdsUsed() - 1;
    }
    m_text = bird != nullptr ? describeBirdBody(session.world().birdBody(*bird)) : std::string();
    if (!m_text.empty() && number != m_told)
    {
        m_told = number;
        view.app().trace().write("notice", {{"text", m_text}});
    }
}

void BirdBodyNotice::drawScreen(sf::RenderTarget& target, PlayView& view)
{
    const sf::Font* font = view.app().ui().font();
    if (m_text.empty() || font == nullptr)
        return;
    const float scale = view.app().ui().scale();
    const unsigned size = view.app().ui().textSize(15.0f);
    const float width = std::min(static_cast<float>(target.getSize().x) * 0.5f, 560.0f * scale);
    const std::vector<std::string> lines = wrapText(*font, m_text, size, width);
    const float lineHeight = font->getLineSpacing(size);
    const float pad = 8.0f * scale;
    const float left = 0.5f * (static_cast<float>(target.getSize().x) - width) - pad;
    const float top = 96.0f * scale; // under the HUD's aim readout
    sf::RectangleShape box({width + 2.0f * pad, lineHeight * static_cast<float>(lines.size()) + 2.0f * pad});
    box.setPosition(left, top);
    recordScreenRegion("bird body notice", {{left, top}, box.getSize()});
    box.setFillColor(palette::kPanel);
    box.setOutlineColor(palette::kStar);
    box.setOutlineThickness(1.5f * scale);
    target.draw(box);
    float y = top + pad;
    for (const std::string& line : lines)
    {
        drawLabel(target, *font, utf8(line), {left + pad, y}, size, palette::kText);
        y += lineHeight;
    }
}

} // namespace abalike::app
