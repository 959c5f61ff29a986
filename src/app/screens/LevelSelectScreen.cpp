#include "screens/LevelSelectScreen.hpp"

#include <abalike/teach/TextValues.hpp>

#include "editor/EditorSource.hpp"
#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "render/TextFormat.hpp"
#include "screens/Navigation.hpp"
#include "shell/AppContext.hpp"
#include "shell/Navigator.hpp"
#include "shell/PlayerProgress.hpp"
#include "shell/UiMetrics.hpp"

#include <SFML/Graphics/RectangleShape.hpp>
#include <algorithm>
#include <map>

namespace abalike::app
{

namespace
{
/// A level's concept with its {...} values filled, computed once per level and text (a range costs a chart).
const std::string& filledConcept(const LevelDef& level)
{
    static std::map<std::pair<std::string, std::string>, std::string> filled;
    const auto key = std::make_pair(level.sourcePath + "\n" + level.id, level.lesson);
    auto it = filled.find(key);
    if (it == filled.end())
        it = filled.emplace(key, levelText(level.lesson, level, Catalog::builtin())).first;
    return it->second;
}
} // namespace

LevelSelectScreen::LevelSelectScreen(AppContext& app) : m_app(app), m_selected(continueLevel(app)) {}

std::pair<std::size_t, std::size_t> LevelSelectScreen::place(std::size_t index) const
{
    const Campaign& campaign = m_app.progress().campaign();
    const std::size_t episode = campaign.levels[index].episode;
    std::size_t first = index;
    while (first > 0 && campaign.levels[first - 1].episode == episode)
        --first;
    return {episode, index - first};
}

void LevelSelectScreen::move(int dx, int dy)
{
    const Campaign& campaign = m_app.progress().campaign();
    if (campaign.levels.empty())
        return;
    const auto [episode, position] = place(m_selected);
    if (dx != 0)
    {
        const auto target = static_cast<long>(m_selected) + dx;
        if (target >= 0 && target < static_cast<long>(campaign.levels.size()))
            m_selected = static_cast<std::size_t>(target);
        return;
    }
    const long wanted = static_cast<long>(episode) + dy;
    if (wanted < 0 || wanted >= static_cast<long>(campaign.episodes.size()))
        return;
    // Same column in the other episode, or its last level if it is shorter.
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < campaign.levels.size(); ++i)
        if (campaign.levels[i].episode == static_cast<std::size_t>(wanted) && (!best || place(i).second <= position))
            best = i;
    if (best)
        m_selected = *best;
}

void LevelSelectScreen::play(std::size_t index)
{
    m_selected = index;
    if (m_app.progress().isUnlocked(m_app.progress().campaign().levels[index].key))
        playCampaignLevel(m_app, index);
}

std::optional<std::size_t> LevelSelectScreen::tileAt(int x, int y) const
{
    for (std::size_t i = 0; i < m_tiles.size(); ++i)
        if (m_tiles[i].contains(static_cast<float>(x), static_cast<float>(y)))
            return i;
    return std::nullopt;
}

void LevelSelectScreen::handleEvent(const sf::Event& event)
{
    switch (event.type)
    {
    case sf::Event::KeyPressed:
        switch (event.key.code)
        {
        case sf::Keyboard::Escape:
        case sf::Keyboard::Backspace:
            m_app.navigator().screens().pop();
            break;
        case sf::Keyboard::Left:
        case sf::Keyboard::A:
            move(-1, 0);
            break;
        case sf::Keyboard::Right:
        case sf::Keyboard::D:
            move(1, 0);
            break;
        case sf::Keyboard::Up:
        case sf::Keyboard::W:
            move(0, -1);
            break;
        case sf::Keyboard::Down:
        case sf::Keyboard::S:
            move(0, 1);
            break;
        case sf::Keyboard::Enter:
        case sf::Keyboard::Space:
            if (!m_app.progress().campaign().levels.empty())
                play(m_selected);
            break;
        case sf::Keyboard::E:
            // The level editor on the selected level (issue 12), whether or not it is unlocked.
            if (!m_app.progress().campaign().levels.empty())
            {
                const CampaignLevel& level = m_app.progress().campaign().levels[m_selected];
                openEditor(m_app, EditorSource{level.level, level.path, {}, false});
            }
            break;
        default:
            break;
        }
        break;
    case sf::Event::MouseMoved:
        if (const std::optional<std::size_t> tile = tileAt(event.mouseMove.x, event.mouseMove.y))
            m_selected = *tile;
        break;
    case sf::Event::MouseButtonPressed:
        if (event.mouseButton.button == sf::Mouse::Left)
            m_pressed = tileAt(event.mouseButton.x, event.mouseButton.y);
        break;
    case sf::Event::MouseButtonReleased:
        if (event.mouseButton.button == sf::Mouse::Left)
        {
            const std::optional<std::size_t> tile = tileAt(event.mouseButton.x, event.mouseButton.y);
            if (tile && tile == m_pressed)
                play(*tile);
            m_pressed.reset();
        }
        break;
    default:
        break;
    }
}

void LevelSelectScreen::draw(sf::RenderTarget& target)
{
    const Campaign& campaign = m_app.progress().campaign();
    const sf::Font* font = m_app.ui().font();
    const float scale = m_app.ui().scale();
    const sf::Vector2f window(target.getSize());
    Mesh sky;
    sky.addGradientRect({0.0f, 0.0f}, window, palette::kMenuTop, palette::kMenuBottom);
    sky.draw(target);

    const unsigned titleSize = m_app.ui().textSize(34.0f);
    const unsigned episodeSize = m_app.ui().textSize(18.0f);
    const unsigned tileSize = m_app.ui().textSize(22.0f);
    const unsigned smallSize = m_app.ui().textSize(14.0f);
    const unsigned detailSize = m_app.ui().textSize(18.0f);
    const float margin = 24.0f * scale;
    float y = margin;
    if (font != nullptr)
    {
        drawLabel(target, *font, utf8("Choose a level"), {0.5f * window.x, y}, titleSize, palette::kText,
                  Align::Centre);
        y += font->getLineSpacing(titleSize) + 8.0f * scale;
    }

    // One row per episode: its title on the left, its levels as tiles.
    std::size_t mostLevels = 1;
    for (std::size_t e = 0; e < campaign.episodes.size(); ++e)
        mostLevels = std::max(mostLevels, campaign.episodes[e].levelPaths.size());
    const float labelWidth = std::min(0.3f * window.x, 250.0f * scale);
    const float gap = 10.0f * scale;
    const float available = window.x - 2.0f * margin - labelWidth - gap;
    const float tileWidth = std::min(130.0f * scale, (available - gap * static_cast<float>(mostLevels - 1)) /
                                                         static_cast<float>(mostLevels));
    const float detailHeight = font != nullptr ? 3.0f * font->getLineSpacing(detailSize) + 16.0f * scale : 0.0f;
    const float rowsHeight = window.y - y - detailHeight - 2.0f * margin;
    const float tileHeight =
        std::clamp(rowsHeight / static_cast<float>(std::max<std::size_t>(1, campaign.episodes.size())) - gap,
                   30.0f * scale, 88.0f * scale);

    m_tiles.assign(campaign.levels.size(), {});
    m_mesh.clear();
    std::vector<std::size_t> inEpisode(campaign.episodes.size(), 0);
    for (std::size_t i = 0; i < campaign.levels.size(); ++i)
    {
        const CampaignLevel& entry = campaign.levels[i];
        const float rowTop = y + static_cast<float>(entry.episode) * (tileHeight + gap);
        const float left =
            margin + labelWidth + gap + static_cast<float>(inEpisode[entry.episode]++) * (tileWidth + gap);
        m_tiles[i] = {left, rowTop, tileWidth, tileHeight};
    }
    for (std::size_t e = 0; e < campaign.episodes.size() && font != nullptr; ++e)
    {
        const float rowTop = y + static_cast<float>(e) * (tileHeight + gap);
        const std::string label = "Episode " + campaign.episodes[e].id;
        drawLabel(target, *font, utf8(label), {margin, rowTop}, episodeSize, palette::kStar);
        const std::vector<std::string> lines =
            wrapText(*font, campaign.episodes[e].title, smallSize, labelWidth - 8.0f * scale);
        float lineY = rowTop + font->getLineSpacing(episodeSize);
        for (std::size_t l = 0;
             l < lines.size() && lineY + font->getLineSpacing(smallSize) <= rowTop + tileHeight + 2.0f;
             ++l, lineY += font->getLineSpacing(smallSize))
            drawLabel(target, *font, utf8(lines[l]), {margin, lineY}, smallSize, palette::kText);
    }

    for (std::size_t i = 0; i < campaign.levels.size(); ++i)
    {
        const sf::FloatRect& tile = m_tiles[i];
        const std::string& id = campaign.levels[i].key;
        const bool unlocked = m_app.progress().isUnlocked(id);
        const bool selected = i == m_selected;
        sf::RectangleShape box({tile.width, tile.height});
        box.setPosition(tile.left, tile.top);
        box.setFillColor(unlocked ? (selected ? palette::kButtonSelected : palette::kButton) : palette::kTileLocked);
        box.setOutlineThickness(selected ? 3.0f * scale : 1.5f * scale);
        box.setOutlineColor(selected ? palette::kStar : palette::kButtonOutline);
        target.draw(box);

        const auto record = m_app.progress().current().levels.find(id);
        const int stars = record == m_app.progress().current().levels.end() ? 0 : record->second.stars;
        const float starRadius = std::min(9.0f * scale, 0.1f * tile.width);
        const float starsY = tile.top + tile.height - starRadius - 6.0f * scale;
        for (int s = 0; s < 3 && unlocked; ++s)
        {
            const sf::Vector2f centre(tile.left + 0.5f * tile.width + static_cast<float>(s - 1) * 2.3f * starRadius,
                                      starsY);
            m_mesh.addStar(centre, starRadius, 0.45f * starRadius, s < stars ? palette::kStar : palette::kStarEmpty);
        }
        if (font != nullptr)
        {
            const sf::Color colour = unlocked ? palette::kText : palette::kTextDisabled;
            // Its number, its place in the episode (a pack's episode heading already names the pack).
            drawLabel(target, *font, utf8(campaign.levels[i].number),
                      {tile.left + 0.5f * tile.width, tile.top + 4.0f * scale}, tileSize, colour, Align::Centre);
            if (!unlocked)
                drawLabel(target, *font, utf8("locked"),
                          {tile.left + 0.5f * tile.width, tile.top + font->getLineSpacing(tileSize)}, smallSize, colour,
                          Align::Centre);
        }
    }
    m_mesh.draw(target);

    // The selected level, in words.
    if (font == nullptr || campaign.levels.empty())
        return;
    const CampaignLevel& chosen = campaign.levels[m_selected];
    const bool unlocked = m_app.progress().isUnlocked(chosen.key);
    float detailY = window.y - margin - detailHeight;
    const auto record = m_app.progress().current().levels.find(chosen.key);
    std::string heading = chosen.number + "  " + chosen.level.title;
    if (record != m_app.progress().current().levels.end())
        heading += "   best " + formatPoints(record->second.bestScore);
    else if (!unlocked)
        heading += "   (win the level before it to unlock)";
    drawLabel(target, *font, utf8(heading), {margin, detailY}, detailSize, palette::kStar);
    drawLabel(target, *font, utf8("E: open in the editor"), {window.x - margin, detailY}, smallSize, palette::kTextDim,
              Align::Right);
    detailY += font->getLineSpacing(detailSize);
    const std::vector<std::string> lesson =
        wrapText(*font, filledConcept(chosen.level), smallSize, window.x - 2.0f * margin);
    for (std::size_t l = 0; l < lesson.size() && l < 3; ++l, detailY += font->getLineSpacing(smallSize))
        drawLabel(target, *font, utf8(lesson[l]), {margin, detailY}, smallSize, palette::kText);
}

} // namespace abalike::app
