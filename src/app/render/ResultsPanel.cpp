#include "render/ResultsPanel.hpp"

#include "render/Hud.hpp"
#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "render/TextFormat.hpp"

#include <SFML/Graphics/RectangleShape.hpp>
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace abalike::app
{

namespace
{
struct ScoreLine
{
    std::string label;
    int points = 0;
};

std::vector<ScoreLine> scoreLines(const ScoreBreakdown& score)
{
    return {
        {"Blocks destroyed (" + std::to_string(score.blocksDestroyed) + ")", score.blockPoints},
        {"Pigs defeated (" + std::to_string(score.pigsDefeated) + ")", score.pigPoints},
        {"Unused birds (" + std::to_string(score.unusedBirds) + ")", score.unusedBirdBonus},
        {"Efficiency bonus", score.efficiencyBonus},
        {"Accuracy bonus (" + std::to_string(score.accurateShots) + (score.accurateShots == 1 ? " shot)" : " shots)"),
         score.accuracyBonus},
    };
}
} // namespace

sf::FloatRect ResultsPanel::draw(sf::RenderTarget& target, sf::Vector2u size, const GameSession& session, float scale,
                                 float reserveBelow, const std::vector<std::string>& notes)
{
    const bool won = session.phase() == Phase::Won;
    const sf::Vector2f window(size);

    // Dim the scene behind the card.
    sf::RectangleShape shade(window);
    shade.setFillColor(sf::Color(0, 0, 0, 90));
    target.draw(shade);

    // Size the card to its content.
    const unsigned titleSize = static_cast<unsigned>(34.0f * scale);
    const unsigned lineSize = static_cast<unsigned>(19.0f * scale);
    const unsigned totalSize = static_cast<unsigned>(23.0f * scale);
    const unsigned noteSize = static_cast<unsigned>(16.0f * scale);
    const float starRadius = 30.0f * scale;
    const float pad = 18.0f * scale;
    const auto spacing = [this](unsigned size)
    {
        return m_font != nullptr ? m_font->getLineSpacing(size) : 0.0f;
    };
    const ScoreBreakdown score = session.score();
    const std::vector<ScoreLine> lines = scoreLines(score);
    const float contentHeight =
        spacing(titleSize) + 4.0f * scale + 2.6f * starRadius + static_cast<float>(lines.size()) * spacing(lineSize) +
        10.0f * scale + spacing(totalSize) +
        (notes.empty() ? 0.0f : 8.0f * scale + static_cast<float>(notes.size()) * spacing(noteSize));
    const float width = std::min(window.x - 20.0f, 470.0f * scale);
    const float height = std::min(window.y - 20.0f - reserveBelow, contentHeight + 2.0f * pad);
    const sf::Vector2f topLeft(0.5f * (window.x - width), std::max(10.0f, 0.5f * (window.y - height - reserveBelow)));
    const sf::FloatRect cardRect(topLeft, {width, height});
    sf::RectangleShape card({width, height});
    card.setPosition(topLeft);
    card.setFillColor(sf::Color(24, 34, 56, 235));
    card.setOutlineColor(won ? palette::kStar : sf::Color(200, 80, 70));
    card.setOutlineThickness(3.0f * scale);
    target.draw(card);

    const float centreX = topLeft.x + 0.5f * width;
    float y = topLeft.y + pad;
    if (m_font != nullptr)
    {
        const std::string title = won ? std::string("Level complete!")
                                  : session.outOfTime() && session.level().timeLimitS
                                      ? "Out of time (" + formatFixed(*session.level().timeLimitS, 0) + " s)"
                                      : std::string("Out of birds");
        drawLabel(target, *m_font, utf8(title), {centreX, y}, titleSize,
                  won ? palette::kStar : sf::Color(255, 150, 130), Align::Centre);
        y += m_font->getLineSpacing(titleSize) + 4.0f * scale;
    }

    // Stars: the middle one larger and raised, like a podium.
    m_stars.clear();
    const int earned = session.stars();
    for (int i = 0; i < 3; ++i)
    {
        const float big = (i == 1) ? 1.2f : 1.0f;
        const sf::Vector2f centre(centreX + static_cast<float>(i - 1) * 2.4f * starRadius,
                                  y + starRadius * (i == 1 ? 1.0f : 1.25f));
        m_stars.addStar(centre, big * starRadius + 3.0f * scale, big * 0.45f * starRadius + 2.0f * scale,
                        sf::Color(12, 16, 28));
        m_stars.addStar(centre, big * starRadius, big * 0.45f * starRadius,
                        i < earned ? palette::kStar : palette::kStarEmpty);
    }
    m_stars.draw(target);
    y += 2.6f * starRadius;
    if (m_font == nullptr)
        return cardRect;

    const float lineHeight = m_font->getLineSpacing(lineSize);
    const float left = topLeft.x + 30.0f * scale;
    const float right = topLeft.x + width - 30.0f * scale;
    for (const ScoreLine& line : lines)
    {
        drawLabel(target, *m_font, utf8(line.label), {left, y}, lineSize, palette::kTextDim);
        drawLabel(target, *m_font, utf8(formatPoints(line.points)), {right, y}, lineSize, palette::kText, Align::Right);
        y += lineHeight;
    }
    sf::RectangleShape rule({right - left, std::max(1.0f, 2.0f * scale)});
    rule.setPosition(left, y + 4.0f * scale);
    rule.setFillColor(palette::kTextDim);
    target.draw(rule);
    y += 10.0f * scale;
    drawLabel(target, *m_font, utf8("Total"), {left, y}, totalSize, palette::kText);
    drawLabel(target, *m_font, utf8(formatPoints(score.total())), {right, y}, totalSize, palette::kStar, Align::Right);
    y += spacing(totalSize) + 8.0f * scale;
    for (const std::string& note : notes)
    {
        drawLabel(target, *m_font, utf8(fitToWidth(*m_font, note, noteSize, right - left, Cut::AtWord)), {left, y},
                  noteSize, palette::kText);
        y += spacing(noteSize);
    }
    return cardRect;
}

} // namespace abalike::app
