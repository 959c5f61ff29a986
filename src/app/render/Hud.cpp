#include "render/Hud.hpp"

#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "render/TextFormat.hpp"

#include <SFML/Graphics/RectangleShape.hpp>
#include <algorithm>
#include <cmath>

namespace abalike::app
{

namespace
{
unsigned scaled(float scale, float size)
{
    return static_cast<unsigned>(std::max(9.0f, std::round(size * scale)));
}

void panel(sf::RenderTarget& target, sf::FloatRect rect)
{
    sf::RectangleShape box({rect.width, rect.height});
    box.setPosition(rect.left, rect.top);
    box.setFillColor(palette::kPanel);
    target.draw(box);
}
} // namespace

float hudScale(sf::Vector2u size)
{
    return std::clamp(std::min(static_cast<float>(size.x) / 1280.0f, static_cast<float>(size.y) / 720.0f), 0.55f, 2.0f);
}

void Hud::draw(sf::RenderTarget& target, sf::Vector2u size, const GameSession& session,
               const std::optional<AimReadout>& aim) const
{
    if (m_font == nullptr)
        return;
    const float scale = hudScale(size);
    const float statusBottom = drawStatus(target, scale, session);
    drawEnvironment(target, statusBottom + 6.0f * scale, scale, session.level());
    if (aim)
        drawAim(target, size, scale, *aim);
    else if (session.canActivateAbility())
        drawAbilityPrompt(target, size, scale, session);
    if (!session.finished())
        drawHint(target, size, scale, session.level());
}

float Hud::drawStatus(sf::RenderTarget& target, float scale, const GameSession& session) const
{
    const LevelDef& level = session.level();
    const unsigned titleSize = scaled(scale, 24.0f);
    const unsigned lineSize = scaled(scale, 19.0f);
    const sf::String title = utf8("Level " + level.id + ": " + level.title);
    const sf::String score = utf8("Score  " + formatPoints(session.score().total()));
    const sf::String counts = utf8("Birds left  " + std::to_string(session.birdsRemaining()) + "     Pigs left  " +
                                   std::to_string(session.pigsRemaining()));

    sf::String time;
    if (level.timeLimitS)
        time = utf8("Time  " + formatFixed(std::min(session.simTime(), *level.timeLimitS), 1) + " / " +
                    formatFixed(*level.timeLimitS, 0) + " s");

    const float margin = 12.0f * scale;
    const float pad = 10.0f * scale;
    const float titleHeight = m_font->getLineSpacing(titleSize);
    const float lineHeight = m_font->getLineSpacing(lineSize);
    const float width = std::max({measureText(*m_font, title, titleSize).x, measureText(*m_font, score, lineSize).x,
                                  measureText(*m_font, counts, lineSize).x, measureText(*m_font, time, lineSize).x});
    const float lines = time.isEmpty() ? 2.0f : 3.0f;
    const float height = titleHeight + lines * lineHeight + 2.0f * pad;
    panel(target, {margin, margin, width + 2.0f * pad, height});

    sf::Vector2f at(margin + pad, margin + pad);
    drawLabel(target, *m_font, title, at, titleSize, palette::kText);
    at.y += titleHeight;
    drawLabel(target, *m_font, score, at, lineSize, palette::kStar);
    at.y += lineHeight;
    drawLabel(target, *m_font, counts, at, lineSize, palette::kTextDim);
    if (!time.isEmpty())
    {
        at.y += lineHeight;
        drawLabel(target, *m_font, time, at, lineSize, palette::kTextDim);
    }
    return margin + height;
}

void Hud::drawEnvironment(sf::RenderTarget& target, float top, float scale, const LevelDef& level) const
{
    const EnvironmentDef& air = level.environment;
    std::string text = "g " + formatFixed(air.gravity, 2) + " m/s\u00B2   ";
    if (air.airDensity <= 0.0)
        text += "vacuum (no drag)";
    else
        text += "air " + formatFixed(air.airDensity, 2) + " kg/m\u00B3";
    if (air.gusts)
        text += "   gusty";
    if (air.windX != 0.0 || air.windY != 0.0)
    {
        const double windSpeed = std::hypot(air.windX, air.windY);
        text += "   wind " + formatFixed(windSpeed, 1) + " m/s " + (air.windX >= 0.0 ? "\u2192" : "\u2190");
    }
    const unsigned textSize = scaled(scale, 16.0f);
    const sf::String label = utf8(text);
    const float margin = 12.0f * scale;
    const float pad = 7.0f * scale;
    const float width = measureText(*m_font, label, textSize).x;
    panel(target, {margin, top, width + 2.0f * pad, m_font->getLineSpacing(textSize) + 2.0f * pad});
    drawLabel(target, *m_font, label, {margin + pad, top + pad}, textSize, palette::kTextDim);
}

void Hud::drawAim(sf::RenderTarget& target, sf::Vector2u size, float scale, const AimReadout& aim) const
{
    const unsigned mainSize = scaled(scale, 21.0f);
    const unsigned lessonSize = scaled(scale, 16.0f);
    const sf::String main = utf8("angle " + formatFixed(aim.angleDeg, 1) + "\u00B0    force " +
                                 formatFixed(aim.forceN, 0) + " N    speed " + formatFixed(aim.speedMps, 1) + " m/s");
    const sf::String lesson = utf8("v\u2080 = F t / m = " + formatFixed(aim.forceN, 0) + " N \u00D7 " +
                                   formatFixed(aim.releaseTimeS, 2) + " s / " + formatFixed(aim.massKg, 1) + " kg");
    const float pad = 10.0f * scale;
    const float mainHeight = m_font->getLineSpacing(mainSize);
    const float width =
        std::max(measureText(*m_font, main, mainSize).x, measureText(*m_font, lesson, lessonSize).x) + 2.0f * pad;
    const float centre = 0.5f * static_cast<float>(size.x);
    const float top = 12.0f * scale;
    panel(target, {centre - 0.5f * width, top, width, mainHeight + m_font->getLineSpacing(lessonSize) + 2.0f * pad});
    drawLabel(target, *m_font, main, {centre, top + pad}, mainSize, palette::kText, Align::Centre);
    drawLabel(target, *m_font, lesson, {centre, top + pad + mainHeight}, lessonSize, palette::kTextDim, Align::Centre);
}

void Hud::drawAbilityPrompt(sf::RenderTarget& target, sf::Vector2u size, float scale, const GameSession& session) const
{
    const BirdType* bird = session.shots().empty() ? nullptr : session.catalog().findBird(session.shots().back().bird);
    const std::string ability = bird != nullptr ? bird->ability : "ability";
    const unsigned textSize = scaled(scale, 21.0f);
    const sf::String text = utf8("Click or Space: " + ability + "!");
    const float pad = 10.0f * scale;
    const float width = measureText(*m_font, text, textSize).x + 2.0f * pad;
    const float centre = 0.5f * static_cast<float>(size.x);
    const float top = 12.0f * scale;
    panel(target, {centre - 0.5f * width, top, width, m_font->getLineSpacing(textSize) + 2.0f * pad});
    drawLabel(target, *m_font, text, {centre, top + pad}, textSize, palette::kStar, Align::Centre);
}

void Hud::drawHint(sf::RenderTarget& target, sf::Vector2u size, float scale, const LevelDef& level) const
{
    const unsigned hintSize = scaled(scale, 18.0f);
    const unsigned keysSize = scaled(scale, 14.0f);
    const float centre = 0.5f * static_cast<float>(size.x);
    const float keysHeight = m_font->getLineSpacing(keysSize);
    const float bottom = static_cast<float>(size.y) - 8.0f * scale;
    drawLabel(target, *m_font,
              utf8("Mouse: drag the bird back   \u00B7   Keys: \u2191\u2193 angle, \u2190\u2192 power, Space launch   "
                   "\u00B7   R restart   \u00B7   Esc pause   \u00B7   F1 help"),
              {centre, bottom - keysHeight}, keysSize, palette::kTextDim, Align::Centre);
    if (!level.hints.empty())
        drawLabel(target, *m_font, utf8(level.hints.front()),
                  {centre, bottom - keysHeight - m_font->getLineSpacing(hintSize)}, hintSize, palette::kText,
                  Align::Centre);
}

} // namespace abalike::app
