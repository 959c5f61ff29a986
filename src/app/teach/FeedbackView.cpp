#include "teach/FeedbackView.hpp"

#include "render/Label.hpp"
#include "render/LabelPlacement.hpp"
#include "render/Palette.hpp"
#include "teach/TeachDraw.hpp"

#include <abalike/teach/ShotFeedback.hpp>
#include <algorithm>

namespace abalike::app
{

void FeedbackView::reset()
{
    m_firstAim.reset();
    m_shotsSeen = 0;
    m_done = false;
    m_sentences.clear();
}

void FeedbackView::update(const GameSession& session, const std::optional<AimReadout>& aim)
{
    const std::vector<ShotRecord>& shots = session.shots();
    if (shots.size() != m_shotsSeen)
    {
        // A new shot (or a restart): the last shot's words go until this one has something to say.
        m_shotsSeen = shots.size();
        m_done = false;
        m_sentences.clear();
        m_firstAim.reset();
    }
    if (aim && !m_sentences.empty())
    {
        const std::pair<double, double> now{aim->angleDeg, aim->speedMps};
        if (!m_firstAim)
            m_firstAim = now;
        else if (*m_firstAim != now)
            m_sentences.clear(); // the player is aiming the next bird: the sentences have done their work
    }
    if (m_done || shots.empty())
        return;
    const ShotRecord& shot = shots.back();
    const bool flightOver = session.phase() != Phase::Flying || session.world().bird() == nullptr;
    if (!shot.actualContact && !flightOver)
        return;
    m_done = true;
    try
    {
        m_sentences = shotFeedback(session.level(), session.catalog(), shot, session.world().dt());
    }
    catch (const std::exception&)
    {
        m_sentences.clear(); // no words rather than no game
    }
}

void FeedbackView::draw(sf::RenderTarget& target, const sf::Font& font, float bottom, float top,
                        std::span<const sf::FloatRect> avoid, float maxWidth, unsigned rowSize, float scale) const
{
    if (m_sentences.empty())
        return;
    std::vector<std::string> lines;
    for (const std::string& sentence : m_sentences)
        for (std::string& line : wrapText(font, sentence, rowSize, maxWidth))
            lines.push_back(std::move(line));
    const float rowHeight = font.getLineSpacing(rowSize);
    float width = 0.0f;
    for (const std::string& line : lines)
        width = std::max(width, measureText(font, utf8(line), rowSize).x);
    const float pad = 8.0f * scale;
    const float height = rowHeight * static_cast<float>(lines.size()) + 2.0f * pad;
    const float centre = 0.5f * static_cast<float>(target.getSize().x);
    sf::FloatRect rect(centre - 0.5f * width - pad, bottom - height, width + 2.0f * pad, height);
    const sf::FloatRect above(rect.left, top, rect.width, rect.height);
    if (coveredArea(rect, avoid) > 0.0f && coveredArea(above, avoid) <= 0.0f)
        rect = above; // the structure reaches down here: the sentences go up into the sky
    drawTeachPanel(target, rect, scale, "feedback");
    float y = rect.top + pad;
    for (const std::string& line : lines)
    {
        drawLabel(target, font, utf8(line), {centre, y}, rowSize, palette::kText, Align::Centre);
        y += rowHeight;
    }
}

} // namespace abalike::app
