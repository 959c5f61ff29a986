#include "render/Hud.hpp"

#include <abalike/level/WorldTheme.hpp>
#include <abalike/teach/TextValues.hpp>

#include "render/Label.hpp"
#include "render/LabelPlacement.hpp"
#include "render/Palette.hpp"
#include "render/ScreenRegions.hpp"
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

bool leavesInView(const sf::FloatRect& rect, std::span<const sf::FloatRect> keepClear)
{
    return coveredArea(rect, keepClear) <= 0.0f;
}

void panel(sf::RenderTarget& target, sf::FloatRect rect, std::string_view name)
{
    recordScreenRegion(name, rect);
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
               const std::optional<AimReadout>& aim, PlayMode mode, std::string_view levelLabel, float textScale,
               float reservedRightPx, std::span<const sf::FloatRect> keepClear) const
{
    if (m_font == nullptr)
        return;
    const float scale = hudScale(size) * textScale;
    sf::FloatRect status;
    {
        const TextKindScope kind(TextKind::Hud);
        status = drawStatus(target, size, scale, session, levelLabel, mode, keepClear);
    }
    const float environmentBottom =
        drawEnvironment(target, status.top + status.height + 6.0f * scale, scale, session.level(), mode, keepClear);
    const TopRow row{size,
                     scale,
                     status.left + status.width + 8.0f * scale,
                     static_cast<float>(size.x) - reservedRightPx - 8.0f * scale,
                     environmentBottom + 6.0f * scale,
                     static_cast<float>(size.y) - bottomTextHeight(size, session.level(), textScale) - 6.0f * scale,
                     keepClear};
    if (aim && mode == PlayMode::Game)
        drawPowerBar(target, row, *aim);
    else if (aim)
        drawAim(target, row, *aim);
    else if (session.canActivateAbility())
    {
        const TextKindScope kind(TextKind::Hud);
        drawAbilityPrompt(target, row, session);
    }
    if (!session.finished())
        drawHint(target, size, scale, session.level(), keepClear);
}

std::optional<sf::Vector2f> Hud::TopRow::spot(sf::Vector2f stripSize) const
{
    const auto clear = [&](sf::Vector2f corner)
    {
        return leavesInView({corner, stripSize}, keepClear);
    };
    const float top = 12.0f * scale;
    if (right - left >= stripSize.x)
        for (const float x : {std::clamp(0.5f * (static_cast<float>(size.x) - stripSize.x), left, right - stripSize.x),
                              left, right - stripSize.x})
            if (clear({x, top}))
                return sf::Vector2f(x, top);
    for (float y = below; y == below || y + stripSize.y <= lowest; y += 0.5f * stripSize.y)
        if (clear({12.0f * scale, y}))
            return sf::Vector2f(12.0f * scale, y);
    return std::nullopt;
}

sf::FloatRect Hud::drawStatus(sf::RenderTarget& target, sf::Vector2u size, float scale, const GameSession& session,
                              std::string_view levelLabel, PlayMode mode,
                              std::span<const sf::FloatRect> keepClear) const
{
    const LevelDef& level = session.level();
    const unsigned titleSize = scaled(scale, 24.0f);
    const unsigned lineSize = scaled(scale, 19.0f);
    // A long title drops the level's id first (a lesson's id is long), and only then is cut short rather than run
    // under the aim readout.
    const float titleRoom = 0.4f * static_cast<float>(size.x);
    std::string titleText = levelLabel.empty() ? level.title : "Level " + std::string(levelLabel) + ": " + level.title;
    if (measureText(*m_font, utf8(titleText), titleSize).x > titleRoom)
        titleText = level.title;
    const sf::String title = utf8(fitToWidth(*m_font, titleText, titleSize, titleRoom, Cut::AtCharacter));
    const sf::String score = utf8("Score  " + formatPoints(session.score().total()));
    const sf::String counts = utf8("Birds left  " + std::to_string(session.birdsRemaining()) + "     Pigs left  " +
                                   std::to_string(session.pigsRemaining()));

    // Until the first launch the status names the world's slingshot (Learn mode: and what a full pull gives this
    // bird), so that a player who moves between worlds knows the hand's pull means something else here. At large
    // text it shortens, then gives way, rather than widen the panel into the toolbar.
    sf::String band;
    if (const std::optional<SlingshotBand> b = session.band();
        b && session.phase() == Phase::Aiming && session.birdsRemaining() == static_cast<int>(level.birds.size()))
    {
        const std::string world =
            std::string(level.slingshot.ownsBand() ? "This level's" : worldThemeTitle(levelTheme(level))) +
            " slingshot";
        const std::string speed =
            mode == PlayMode::Learn ? "full pull " + formatFixed(b->maxSpeedMps(), 1) + " m/s" : world;
        for (const std::string& text : {mode == PlayMode::Learn ? world + "  " + speed : world, speed})
            if (measureText(*m_font, utf8(text), lineSize).x <= titleRoom)
            {
                band = utf8(text);
                break;
            }
    }

    sf::String time;
    if (level.timeLimitS)
        time = utf8("Time  " + formatFixed(std::min(session.simTime(), *level.timeLimitS), 1) + " / " +
                    formatFixed(*level.timeLimitS, 0) + " s");

    const float margin = 12.0f * scale;
    const float pad = 10.0f * scale;
    const float titleHeight = m_font->getLineSpacing(titleSize);
    const float lineHeight = m_font->getLineSpacing(lineSize);
    const float width = std::max({measureText(*m_font, title, titleSize).x, measureText(*m_font, score, lineSize).x,
                                  measureText(*m_font, counts, lineSize).x, measureText(*m_font, time, lineSize).x,
                                  measureText(*m_font, band, lineSize).x});
    const float lines = 2.0f + (time.isEmpty() ? 0.0f : 1.0f) + (band.isEmpty() ? 0.0f : 1.0f);
    const float height = titleHeight + lines * lineHeight + 2.0f * pad;
    const sf::FloatRect rect(margin, margin, width + 2.0f * pad, height);
    if (!leavesInView(rect, keepClear))
        return rect;
    panel(target, rect, "status");

    sf::Vector2f at(margin + pad, margin + pad);
    drawLabel(target, *m_font, title, at, titleSize, palette::kText);
    at.y += titleHeight;
    drawLabel(target, *m_font, score, at, lineSize, palette::kStar);
    at.y += lineHeight;
    drawLabel(target, *m_font, counts, at, lineSize, palette::kTextDim);
    for (const sf::String* line : {&time, &band})
        if (!line->isEmpty())
        {
            at.y += lineHeight;
            drawLabel(target, *m_font, *line, at, lineSize, palette::kTextDim);
        }
    return rect;
}

float Hud::drawEnvironment(sf::RenderTarget& target, float top, float scale, const LevelDef& level, PlayMode mode,
                           std::span<const sf::FloatRect> keepClear) const
{
    const EnvironmentDef& air = level.environment;
    const bool windy = air.gusts || air.windX != 0.0 || air.windY != 0.0;
    if (mode == PlayMode::Game && !windy)
        return top - 6.0f * scale; // the genre shows the air only when the wind blows
    // Game mode: the wind's way and strength as arrows (one to three); learn mode: gravity and the air in SI units.
    const TextKindScope kind(mode == PlayMode::Game ? TextKind::Hud : TextKind::Physics);
    std::string text;
    if (mode == PlayMode::Game)
    {
        const double windSpeed = std::hypot(air.windX, air.windY);
        const int arrows = windSpeed <= 0.0 ? 0 : windSpeed < 4.0 ? 1 : windSpeed < 8.0 ? 2 : 3;
        text = air.gusts ? "Gusty wind " : "Wind ";
        for (int i = 0; i < std::max(arrows, 1); ++i)
            text += air.windX >= 0.0 ? "\u2192" : "\u2190";
    }
    else
        text = "g " + formatFixed(air.gravity, 2) + " m/s\u00B2   ";
    if (mode == PlayMode::Game)
        ; // the arrows say it all
    else if (air.airDensity <= 0.0)
        text += "vacuum (no drag)";
    else
        text += "air " + formatFixed(air.airDensity, 2) + " kg/m\u00B3";
    if (mode == PlayMode::Learn && air.gusts)
        text += "   gusty";
    if (mode == PlayMode::Learn && (air.windX != 0.0 || air.windY != 0.0))
    {
        const double windSpeed = std::hypot(air.windX, air.windY);
        text += "   wind " + formatFixed(windSpeed, 1) + " m/s " + (air.windX >= 0.0 ? "\u2192" : "\u2190");
    }
    const unsigned textSize = scaled(scale, 16.0f);
    const sf::String label = utf8(text);
    const float margin = 12.0f * scale;
    const float pad = 7.0f * scale;
    const float width = measureText(*m_font, label, textSize).x;
    const float height = m_font->getLineSpacing(textSize) + 2.0f * pad;
    const sf::FloatRect rect(margin, top, width + 2.0f * pad, height);
    if (!leavesInView(rect, keepClear))
        return top + height;
    panel(target, rect, "environment");
    drawLabel(target, *m_font, label, {margin + pad, top + pad}, textSize, palette::kTextDim);
    return top + height;
}

namespace
{
/// The aim's numbers on two lines, split at the separator nearest the middle.
std::pair<std::string, std::string> splitSummary(const std::string& summary)
{
    const std::string dot = " \u00B7 ";
    std::size_t best = std::string::npos;
    for (std::size_t at = summary.find(dot); at != std::string::npos; at = summary.find(dot, at + 1))
        if (best == std::string::npos ||
            std::abs(static_cast<double>(at) - 0.5 * static_cast<double>(summary.size())) <
                std::abs(static_cast<double>(best) - 0.5 * static_cast<double>(summary.size())))
            best = at;
    if (best == std::string::npos)
        return {summary, ""};
    return {summary.substr(0, best), summary.substr(best + dot.size())};
}
} // namespace

void Hud::drawAim(sf::RenderTarget& target, const TopRow& row, const AimReadout& aim) const
{
    const float scale = row.scale;
    const unsigned mainSize = scaled(scale, 21.0f);
    const unsigned lessonSize = scaled(scale, 16.0f);
    const std::string summary = aimSummary(aim);
    const sf::String lesson = utf8(aimLesson(aim));
    const sf::String share = utf8(aimShare(aim));
    const float pad = 10.0f * scale;
    const float mainHeight = m_font->getLineSpacing(mainSize);
    const float lessonHeight = m_font->getLineSpacing(lessonSize);
    const float shareLines = share.isEmpty() ? 1.0f : 2.0f;
    const float summaryWidth = measureText(*m_font, utf8(summary), mainSize).x;
    const auto [firstHalf, secondHalf] = splitSummary(summary);
    // The whole readout; with no place clear of what it must leave in view (at large text it spans the window), the
    // numbers alone (the angle, the pull, the force, the energy and the speed, without how they follow from each
    // other) on one line, then on two.
    struct Form
    {
        std::vector<std::string> numberLines;
        bool lessons;
        sf::Vector2f size;
    };
    const Form forms[] = {
        {{summary},
         true,
         {std::max(
              {summaryWidth, measureText(*m_font, lesson, lessonSize).x, measureText(*m_font, share, lessonSize).x}) +
              2.0f * pad,
          mainHeight + shareLines * lessonHeight + 2.0f * pad}},
        {{summary}, false, {summaryWidth + 2.0f * pad, mainHeight + 2.0f * pad}},
        {{firstHalf, secondHalf},
         false,
         {std::max(measureText(*m_font, utf8(firstHalf), mainSize).x,
                   measureText(*m_font, utf8(secondHalf), mainSize).x) +
              2.0f * pad,
          2.0f * mainHeight + 2.0f * pad}},
    };
    for (const Form& form : forms)
    {
        const std::optional<sf::Vector2f> spot = row.spot(form.size);
        if (!spot)
            continue;
        const auto [x, top] = *spot;
        const float centre = x + 0.5f * form.size.x;
        panel(target, {*spot, form.size}, "aim readout");
        float y = top + pad;
        {
            const TextKindScope kind(TextKind::Physics);
            for (const std::string& line : form.numberLines)
            {
                drawLabel(target, *m_font, utf8(line), {centre, y}, mainSize, palette::kText, Align::Centre);
                y += mainHeight;
            }
        }
        if (!form.lessons)
            return;
        const TextKindScope kind(TextKind::Formula);
        drawLabel(target, *m_font, lesson, {centre, y}, lessonSize, palette::kTextDim, Align::Centre);
        if (!share.isEmpty())
        {
            const TextKindScope numbers(TextKind::Physics);
            drawLabel(target, *m_font, share, {centre, y + lessonHeight}, lessonSize, palette::kTextDim, Align::Centre);
        }
        return;
    }
}

void Hud::drawPowerBar(sf::RenderTarget& target, const TopRow& row, const AimReadout& aim) const
{
    const float scale = row.scale;
    const TextKindScope kind(TextKind::Hud);
    const unsigned textSize = scaled(scale, 21.0f);
    const sf::String angle = utf8(formatFixed(aim.angleDeg, 0) + "\u00B0");
    const float pad = 10.0f * scale;
    const float barWidth = 160.0f * scale;
    const float barHeight = 14.0f * scale;
    const float angleWidth = measureText(*m_font, utf8("-88\u00B0"), textSize).x;
    const float width = angleWidth + barWidth + 3.0f * pad;
    const float lineHeight = m_font->getLineSpacing(textSize);
    const std::optional<sf::Vector2f> spot = row.spot({width, lineHeight + 2.0f * pad});
    if (!spot)
        return;
    const auto [x, top] = *spot;
    panel(target, {x, top, width, lineHeight + 2.0f * pad}, "aim readout");
    drawLabel(target, *m_font, angle, {x + pad + angleWidth, top + pad}, textSize, palette::kText, Align::Right);
    // The bar: the pull's share of a full pull, filled from the left, warmer as it fills.
    const float fraction =
        aim.maxPullM > 0.0 ? static_cast<float>(std::clamp(aim.pull.pullM / aim.maxPullM, 0.0, 1.0)) : 0.0f;
    const sf::Vector2f barAt(x + 2.0f * pad + angleWidth, top + pad + 0.5f * (lineHeight - barHeight));
    sf::RectangleShape frame({barWidth, barHeight});
    frame.setPosition(barAt);
    frame.setFillColor(sf::Color(0, 0, 0, 90));
    frame.setOutlineColor(palette::kTextDim);
    frame.setOutlineThickness(1.0f * scale);
    target.draw(frame);
    sf::RectangleShape fill({barWidth * fraction, barHeight});
    fill.setPosition(barAt);
    fill.setFillColor(
        sf::Color(static_cast<sf::Uint8>(120 + 135 * fraction), static_cast<sf::Uint8>(200 - 120 * fraction), 60));
    target.draw(fill);
}

void Hud::drawAbilityPrompt(sf::RenderTarget& target, const TopRow& row, const GameSession& session) const
{
    const float scale = row.scale;
    const BirdType* bird = session.shots().empty() ? nullptr : session.catalog().findBird(session.shots().back().bird);
    const std::string ability = bird != nullptr ? std::string(bird->abilityName()) : "ability";
    const unsigned textSize = scaled(scale, 21.0f);
    const sf::String text = utf8("Click or Space: " + ability + "!");
    const float pad = 10.0f * scale;
    const float width = measureText(*m_font, text, textSize).x + 2.0f * pad;
    const float height = m_font->getLineSpacing(textSize) + 2.0f * pad;
    const std::optional<sf::Vector2f> spot = row.spot({width, height});
    if (!spot)
        return;
    const auto [x, top] = *spot;
    const float centre = x + 0.5f * width;
    panel(target, {x, top, width, height}, "ability prompt");
    drawLabel(target, *m_font, text, {centre, top + pad}, textSize, palette::kStar, Align::Centre);
}

std::vector<Hud::BottomText> Hud::bottomText(sf::Vector2u size, float scale, const LevelDef& level) const
{
    const float maxWidth = static_cast<float>(size.x) - 24.0f * scale;
    std::vector<BottomText> texts;
    const auto add = [&](const std::string& text, unsigned textSize, sf::Color colour, const char* name, TextKind kind)
    {
        texts.push_back({wrapText(*m_font, text, textSize, maxWidth), textSize, colour, name, kind});
    };
    add("Mouse: drag the bird back   \u00B7   Keys: \u2191\u2193 angle, \u2190\u2192 pull, Space launch   \u00B7   "
        "R restart   \u00B7   Esc pause   \u00B7   F1 help",
        scaled(scale, 14.0f), palette::kTextDim, "keys", TextKind::Interface);
    if (!level.hints.empty())
        add(filledHint(level), scaled(scale, 18.0f), palette::kText, "hint", TextKind::Hint);
    return texts;
}

float Hud::bottomTextHeight(sf::Vector2u size, const LevelDef& level, float textScale) const
{
    if (m_font == nullptr)
        return 0.0f;
    const float scale = hudScale(size) * textScale;
    float height = 8.0f * scale;
    for (const BottomText& text : bottomText(size, scale, level))
        height += m_font->getLineSpacing(text.textSize) * static_cast<float>(text.lines.size());
    return height;
}

void Hud::drawHint(sf::RenderTarget& target, sf::Vector2u size, float scale, const LevelDef& level,
                   std::span<const sf::FloatRect> keepClear) const
{
    const auto windowWidth = static_cast<float>(size.x);
    const float margin = 12.0f * scale;
    float bottom = static_cast<float>(size.y) - 8.0f * scale;
    // Bottom up: the keys, then the level's hint, each wrapped to the window at large text sizes; each in the middle
    // of its line, else at the line's left or right end, whichever leaves what it would cover in view.
    for (const BottomText& text : bottomText(size, scale, level))
    {
        const TextKindScope kind(text.kind);
        const float lineHeight = m_font->getLineSpacing(text.textSize);
        const float height = lineHeight * static_cast<float>(text.lines.size());
        bottom -= height;
        float widest = 0.0f;
        for (const std::string& line : text.lines)
            widest = std::max(widest, measureText(*m_font, utf8(line), text.textSize).x);
        const float halfWidest = 0.5f * widest;
        for (const float centre : {0.5f * windowWidth, std::min(0.5f * windowWidth, margin + halfWidest),
                                   std::max(0.5f * windowWidth, windowWidth - margin - halfWidest)})
        {
            const sf::FloatRect rect(centre - halfWidest, bottom, widest, height);
            if (!leavesInView(rect, keepClear))
                continue;
            float y = bottom;
            for (const std::string& line : text.lines)
            {
                drawLabel(target, *m_font, utf8(line), {centre, y}, text.textSize, text.colour, Align::Centre);
                y += lineHeight;
            }
            recordScreenRegion(text.name, rect);
            break;
        }
    }
}

const std::string& Hud::filledHint(const LevelDef& level) const
{
    const std::string& raw = level.hints.front();
    if (raw != m_hintSource || !(level.environment == m_hintAir) || !(level.slingshot == m_hintSlingshot) ||
        m_hintShown.empty())
    {
        m_hintSource = raw;
        m_hintAir = level.environment;
        m_hintSlingshot = level.slingshot;
        m_hintShown = levelText(raw, level, Catalog::builtin());
    }
    return m_hintShown;
}

} // namespace abalike::app
