#include "teach/FeedbackView.hpp"

#include "render/Label.hpp"
#include "render/LabelPlacement.hpp"
#include "render/Palette.hpp"
#include "render/ScreenRegions.hpp"
#include "teach/TeachDraw.hpp"

#include <abalike/teach/ShotFeedback.hpp>
#include <algorithm>
#include <array>
#include <optional>
#include <utility>

namespace abalike::app
{

namespace
{
/// The card's spots come in rows (on the ground just above the HUD's strips at the bottom, above where the hint
/// usually starts, in the sky, halfway), each from the middle, the left and the right edge, then at the sixths of the
/// room between the edges.
constexpr std::size_t kSpotsPerRow = 8;

/// The left edges of a row's spots for a card `width` wide in a window `windowWidth` wide with `margin` at each side.
std::array<float, kSpotsPerRow> rowSpots(float width, float windowWidth, float margin)
{
    const float left = margin;
    const float right = windowWidth - margin - width;
    std::array<float, kSpotsPerRow> spots{0.5f * (windowWidth - width), left, right};
    for (std::size_t k = 1; k + 2 < kSpotsPerRow; ++k)
        spots[k + 2] = left + (right - left) * static_cast<float>(k) / 6.0f;
    return spots;
}
} // namespace

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
    m_shotOver = session.phase() != Phase::Flying;
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
        m_summary = shotSummary(session.level(), session.catalog(), shot, session.world().dt());
        m_spot.reset();
        m_movedDuringShot = false;
    }
    catch (const std::exception&)
    {
        m_sentences.clear(); // no words rather than no game
    }
}

void FeedbackView::draw(sf::RenderTarget& target, const sf::Font& font, float bottom, float top,
                        std::span<const sf::FloatRect> avoid, std::span<const sf::FloatRect> keep, float maxWidth,
                        unsigned rowSize, float scale) const
{
    const TextKindScope kind(TextKind::Physics);
    if (m_sentences.empty())
        return;
    const float windowWidth = static_cast<float>(target.getSize().x);
    const float windowHeight = static_cast<float>(target.getSize().y);
    const float pad = 8.0f * scale;
    std::vector<std::string> full;
    for (const std::string& sentence : m_sentences)
        for (std::string& line : wrapText(font, sentence, rowSize, maxWidth))
            full.push_back(std::move(line));
    // Where the whole card has no room (a small window, large text, many panels), the first sentence's gist on one
    // line, whole or not at all: a sentence cut short would say something else.
    const bool summaryFits =
        measureText(font, utf8(m_summary), rowSize).x <= std::min(maxWidth, windowWidth - 24.0f * scale - 2.0f * pad);
    const std::vector<std::string> summary{summaryFits ? m_summary : std::string()};
    std::vector<sf::FloatRect> panels;
    // The top of the HUD's strips at the bottom (the hint, the keys, a notice): the lowest row sits just above them.
    float strips = windowHeight - 12.0f * scale;
    for (const ScreenRegion& region : screenLayout())
    {
        panels.push_back(region.rect);
        if (region.rect.top > 0.5f * windowHeight)
            strips = std::min(strips, region.rect.top);
    }

    // Candidates in order of preference, row by row (kSpotsPerRow each): just above the strips at the bottom, above
    // where the hint usually starts, up in the sky under the panels already drawn, halfway. The first that covers
    // neither a panel, nor the structure, nor what must stay in view (the slingshot, the flying bird, the landing
    // point, the pigs) wins; otherwise, among those clear of the panels and of what must stay in view, the one
    // covering least of the structure; else the first sentence on one line the same way; else nothing.
    const auto candidatesFor = [&](const std::vector<std::string>& lines)
    {
        float width = 0.0f;
        for (const std::string& line : lines)
            width = std::max(width, measureText(font, utf8(line), rowSize).x);
        const float w = width + 2.0f * pad;
        const float height = font.getLineSpacing(rowSize) * static_cast<float>(lines.size()) + 2.0f * pad;
        std::vector<sf::FloatRect> candidates; // kSpotsPerRow in each row
        const std::array<float, kSpotsPerRow> spots = rowSpots(w, windowWidth, 12.0f * scale);
        for (const float x : spots)
            candidates.emplace_back(x, strips - 6.0f * scale - height, w, height);
        for (const float x : spots)
            candidates.emplace_back(x, bottom - height, w, height);
        for (const float x : spots)
            candidates.emplace_back(x, firstFreeTop(x, w, top, height, 6.0f * scale), w, height);
        const float halfway = std::max(top, 0.5f * (top + bottom - height));
        for (const float x : spots)
            candidates.emplace_back(x, firstFreeTop(x, w, halfway, height, 6.0f * scale), w, height);
        return candidates;
    };
    const auto fits = [&](const sf::FloatRect& rect)
    {
        return rect.left >= 0.0f && rect.top >= 0.0f && rect.left + rect.width <= windowWidth &&
               rect.top + rect.height <= windowHeight && coveredArea(rect, panels) <= 0.0f;
    };
    const auto firstClearOf = [&](const std::vector<sf::FloatRect>& candidates,
                                  std::span<const sf::FloatRect> boxes) -> std::optional<std::size_t>
    {
        for (std::size_t i = 0; i < candidates.size(); ++i)
            if (fits(candidates[i]) && coveredArea(candidates[i], boxes) <= 0.0f)
                return i;
        return std::nullopt;
    };
    const auto draw = [&](const sf::FloatRect& rect, std::size_t spot, bool collapsed)
    {
        m_spot = spot;
        m_collapsed = collapsed;
        drawCard(target, font, rect, collapsed ? summary : full, rowSize, scale);
    };
    // Chosen once per shot's sentences: the card stays put while the structure collapses behind it, and moves only
    // when a panel drawn before it (a label that appeared later) now takes its spot, or as below.
    if (m_spot)
    {
        const std::vector<sf::FloatRect> candidates = candidatesFor(m_collapsed ? summary : full);
        if (*m_spot < candidates.size() && fits(candidates[*m_spot]))
        {
            // Once the next bird is ready (or the level is over) the camera returns to the slingshot: a card that
            // now covers the slingshot, a pig or a block takes the first spot that covers none, if there is one;
            // one that covers the slingshot or a pig, else the first spot that covers neither of those, else its
            // one-line summary where that covers neither. During the shot the camera turns from the bird to the
            // struck structure after the card took its spot: a card that now covers the slingshot, the bird or a
            // pig moves the same way, once.
            const bool coversKeep = coveredArea(candidates[*m_spot], keep) > 0.0f;
            if ((m_shotOver && coveredArea(candidates[*m_spot], avoid) > 0.0f) ||
                (!m_shotOver && !m_movedDuringShot && coversKeep))
            {
                const std::size_t spot = *m_spot;
                // `avoid` holds the slingshot, the bird and (larger) the pigs too: clear of it is clear of `keep`.
                if (const std::optional<std::size_t> clear = firstClearOf(candidates, avoid))
                    m_spot = clear;
                else if (coversKeep)
                {
                    if (const std::optional<std::size_t> clearOfKeep = firstClearOf(candidates, keep))
                        m_spot = clearOfKeep;
                    else if (!m_collapsed && !summary.front().empty())
                    {
                        const std::vector<sf::FloatRect> oneLine = candidatesFor(summary);
                        if (const std::optional<std::size_t> line = firstClearOf(oneLine, keep))
                        {
                            draw(oneLine[*line], *line, true);
                            if (!m_shotOver)
                                m_movedDuringShot = true;
                            return;
                        }
                    }
                }
                if (!m_shotOver && *m_spot != spot)
                    m_movedDuringShot = true;
            }
            else if (!m_shotOver && coversKeep)
            {
                // Moved once already this shot: it may still slide along its row (the bottom one or the one in the
                // sky, never from one to the other) to a spot clear of the structure and of what must stay in view.
                for (std::size_t i = 0; i < candidates.size(); ++i)
                    if (i / kSpotsPerRow == *m_spot / kSpotsPerRow && fits(candidates[i]) &&
                        coveredArea(candidates[i], avoid) <= 0.0f)
                    {
                        m_spot = i;
                        break;
                    }
            }
            // Never over what must stay in view: where its spot now would be (the bird rolled under it), the first
            // spot clear of it, else it is left out this frame.
            if (coveredArea(candidates[*m_spot], keep) > 0.0f)
            {
                const std::optional<std::size_t> clearOfKeep = firstClearOf(candidates, keep);
                if (!clearOfKeep)
                    return;
                m_spot = clearOfKeep;
            }
            draw(candidates[*m_spot], *m_spot, m_collapsed);
            return;
        }
    }
    m_spot.reset();
    // The first spot: among those clear of what must stay in view, the one covering least of the structure (the first
    // that covers none wins); the whole card, or its first sentence on one line where the whole card has no such spot.
    struct Choice
    {
        std::size_t spot = 0;
        sf::FloatRect rect;
        float covered = 0.0f; // of `avoid`
    };
    const auto leastCovering = [&](const std::vector<std::string>& lines) -> std::optional<Choice>
    {
        if (lines.front().empty())
            return std::nullopt;
        const std::vector<sf::FloatRect> candidates = candidatesFor(lines);
        std::optional<Choice> least;
        for (std::size_t i = 0; i < candidates.size(); ++i)
        {
            if (!fits(candidates[i]) || coveredArea(candidates[i], keep) > 0.0f)
                continue;
            const float covered = coveredArea(candidates[i], avoid);
            if (!least || covered < least->covered)
                least = Choice{i, candidates[i], covered};
            if (covered <= 0.0f)
                break;
        }
        return least;
    };
    if (const std::optional<Choice> whole = leastCovering(full))
        draw(whole->rect, whole->spot, false);
    else if (const std::optional<Choice> line = leastCovering(summary))
        draw(line->rect, line->spot, true);
    // Otherwise not even one line has room clear of the panels and of what must stay in view: left out this frame
    // rather than drawn over them.
}

void FeedbackView::drawCard(sf::RenderTarget& target, const sf::Font& font, const sf::FloatRect& rect,
                            const std::vector<std::string>& lines, unsigned rowSize, float scale) const
{
    const float rowHeight = font.getLineSpacing(rowSize);
    const float pad = 8.0f * scale;
    const float centre = rect.left + 0.5f * rect.width;
    drawTeachPanel(target, rect, scale, "feedback");
    float y = rect.top + pad;
    for (const std::string& line : lines)
    {
        drawLabel(target, font, utf8(line), {centre, y}, rowSize, palette::kText, Align::Centre);
        y += rowHeight;
    }
}

} // namespace abalike::app
