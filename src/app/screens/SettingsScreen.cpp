#include "screens/SettingsScreen.hpp"

#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "shell/AppContext.hpp"
#include "shell/Navigator.hpp"
#include "shell/Notices.hpp"
#include "shell/PlayerSettings.hpp"
#include "shell/UiMetrics.hpp"
#include "ui/Card.hpp"

#include <SFML/Graphics/RectangleShape.hpp>
#include <algorithm>
#include <array>
#include <cmath>

namespace abalike::app
{

namespace
{
struct WindowSize
{
    unsigned width;
    unsigned height;
};
constexpr std::array<WindowSize, 5> kSizes{{{960, 540}, {1280, 720}, {1366, 768}, {1600, 900}, {1920, 1080}}};
constexpr std::array<double, 5> kTextScales{1.0, 1.25, 1.5, 1.75, 2.0};

std::string percent(double fraction)
{
    return std::to_string(static_cast<int>(std::lround(fraction * 100.0))) + " %";
}

std::string onOff(bool on)
{
    return on ? "on" : "off";
}

/// The index of the step nearest to a value.
template <class T, std::size_t N, class Distance>
std::size_t nearest(const std::array<T, N>& steps, Distance distance)
{
    std::size_t best = 0;
    for (std::size_t i = 1; i < N; ++i)
        if (distance(steps[i]) < distance(steps[best]))
            best = i;
    return best;
}

std::size_t stepIndex(std::size_t index, int direction, std::size_t count)
{
    // Wraps, so a mouse that only clicks "up" still reaches every value.
    return (index + count + static_cast<std::size_t>(direction + static_cast<int>(count))) % count;
}

const char* labelOf(const std::string& id)
{
    if (id == "effects")
        return "Effects volume";
    if (id == "mute")
        return "Sound";
    if (id == "size")
        return "Window size";
    if (id == "fullscreen")
        return "Full screen";
    if (id == "text")
        return "Text size";
    if (id == "palette")
        return "Colours";
    if (id == "contrast")
        return "High contrast";
    if (id == "motion")
        return "Reduced motion";
    if (id == "teaching")
        return "Teaching overlay";
    if (id == "open")
        return "Open every level";
    if (id == "wording")
        return "Wording";
    if (id == "preview")
        return "Trajectory preview";
    return "Back";
}
} // namespace

const std::vector<std::string>& SettingsScreen::rowIds()
{
    // No music row: the game has no music (settings.json keeps music_volume for the files that have it).
    static const std::vector<std::string> ids{"effects", "mute",     "size",   "fullscreen", "text",
                                              "palette", "contrast", "motion", "teaching",   "preview",
                                              "open",    "wording",  "back"};
    return ids;
}

std::string SettingsScreen::valueText(const std::string& id) const
{
    const Settings& s = m_app.settings().current();
    if (id == "effects")
        return percent(s.effectsVolume);
    if (id == "mute")
        return s.mute ? "muted" : "on";
    if (id == "size")
    {
        if (m_app.settings().sizeFromCommandLine())
            return "set by --size";
        return std::to_string(s.windowWidth) + " \u00D7 " + std::to_string(s.windowHeight);
    }
    if (id == "fullscreen")
        return m_app.settings().sizeFromCommandLine() ? "set by --size" : onOff(s.fullscreen);
    if (id == "text")
        return percent(s.textScale);
    if (id == "palette")
        return s.palette == Palette::ColourBlindSafe ? "colour-blind safe" : "standard";
    if (id == "contrast")
        return onOff(s.highContrast);
    if (id == "motion")
        return onOff(s.reducedMotion);
    if (id == "teaching")
        return onOff(s.teachingOverlay);
    if (id == "open")
        return onOff(s.openAllLevels);
    if (id == "wording")
        return s.wording == Wording::University ? "university (full depth)" : "school (ages 14\u201316)";
    if (id == "preview")
    {
        // Each mode keeps its own preview: the row sets the one of the mode the player is in.
        const PreviewMode preview = s.previewFor(m_app.settings().mode());
        const std::string mode = m_app.settings().mode() == PlayMode::Game ? " (in Play)" : " (in Learn)";
        return (preview == PreviewMode::Full    ? "full path"
                : preview == PreviewMode::Short ? "first dots"
                                                : "off") +
               mode;
    }
    return "";
}

void SettingsScreen::change(const std::string& id, int direction)
{
    Settings s = m_app.settings().current();
    const auto volume = [direction](double v)
    {
        return std::clamp(std::round(v * 10.0) + direction, 0.0, 10.0) / 10.0;
    };
    if (id == "effects")
        s.effectsVolume = volume(s.effectsVolume);
    else if (id == "mute")
        s.mute = !s.mute;
    else if (id == "size" || id == "fullscreen")
    {
        if (m_app.settings().sizeFromCommandLine())
        {
            m_app.notices().notify("The window is set by --size on the command line for this run.");
            return;
        }
        if (id == "fullscreen")
            s.fullscreen = !s.fullscreen;
        else
        {
            const std::size_t at = nearest(kSizes,
                                           [&s](const WindowSize& size)
                                           {
                                               return std::abs(static_cast<double>(size.width) - s.windowWidth) +
                                                      std::abs(static_cast<double>(size.height) - s.windowHeight);
                                           });
            const WindowSize next = kSizes[stepIndex(at, direction, kSizes.size())];
            s.windowWidth = next.width;
            s.windowHeight = next.height;
        }
    }
    else if (id == "text")
    {
        const std::size_t at = nearest(kTextScales, [&s](double scale) { return std::abs(scale - s.textScale); });
        s.textScale = kTextScales[stepIndex(at, direction, kTextScales.size())];
    }
    else if (id == "palette")
        s.palette = s.palette == Palette::Standard ? Palette::ColourBlindSafe : Palette::Standard;
    else if (id == "contrast")
        s.highContrast = !s.highContrast;
    else if (id == "motion")
        s.reducedMotion = !s.reducedMotion;
    else if (id == "teaching")
        s.teachingOverlay = !s.teachingOverlay;
    else if (id == "open")
        s.openAllLevels = !s.openAllLevels;
    else if (id == "wording")
        s.wording = s.wording == Wording::School ? Wording::University : Wording::School;
    else if (id == "preview")
    {
        // full -> first dots -> off, and back the other way.
        PreviewMode& preview = s.previewFor(m_app.settings().mode());
        preview = static_cast<PreviewMode>((static_cast<int>(preview) + (direction < 0 ? 2 : 1)) % 3);
    }
    else
        return;
    m_app.settings().update(s);
}

void SettingsScreen::move(int direction)
{
    const std::size_t count = rowIds().size();
    m_selected = (m_selected + count + static_cast<std::size_t>(direction + static_cast<int>(count))) % count;
}

std::optional<std::size_t> SettingsScreen::rowAt(sf::Vector2f pixel) const
{
    for (std::size_t i = 0; i < m_rects.size(); ++i)
        if (m_rects[i].width > 0.0f && m_rects[i].contains(pixel))
            return i;
    return std::nullopt;
}

void SettingsScreen::handleEvent(const sf::Event& event)
{
    const std::string& id = rowIds()[m_selected];
    switch (event.type)
    {
    case sf::Event::KeyPressed:
        switch (event.key.code)
        {
        case sf::Keyboard::Escape:
            m_app.navigator().screens().pop();
            break;
        case sf::Keyboard::Up:
            move(-1);
            break;
        case sf::Keyboard::Down:
            move(+1);
            break;
        case sf::Keyboard::Tab:
            move(event.key.shift ? -1 : +1);
            break;
        case sf::Keyboard::Left:
            change(id, -1);
            break;
        case sf::Keyboard::Right:
            change(id, +1);
            break;
        case sf::Keyboard::Enter:
        case sf::Keyboard::Space:
            if (id == "back")
                m_app.navigator().screens().pop();
            else
                change(id, +1);
            break;
        default:
            break;
        }
        break;
    case sf::Event::MouseMoved:
        if (const auto row = rowAt({static_cast<float>(event.mouseMove.x), static_cast<float>(event.mouseMove.y)}))
            m_selected = *row;
        break;
    case sf::Event::MouseButtonReleased:
        if (event.mouseButton.button == sf::Mouse::Left)
        {
            const sf::Vector2f at(static_cast<float>(event.mouseButton.x), static_cast<float>(event.mouseButton.y));
            if (const auto row = rowAt(at))
            {
                m_selected = *row;
                const sf::FloatRect& rect = m_rects[*row];
                if (rowIds()[*row] == "back")
                    m_app.navigator().screens().pop();
                else // the value's left half steps down, the rest up
                    change(rowIds()[*row], at.x < rect.left + 0.75f * rect.width ? -1 : +1);
            }
        }
        break;
    case sf::Event::MouseWheelScrolled:
        move(event.mouseWheelScroll.delta > 0.0f ? -1 : +1);
        break;
    default:
        break;
    }
}

void SettingsScreen::draw(sf::RenderTarget& target)
{
    drawScrim(target);
    const sf::Font* font = m_app.ui().font();
    const float scale = m_app.ui().scale();
    const sf::Vector2f window(target.getSize());
    const unsigned titleSize = m_app.ui().textSize(34.0f);
    const unsigned rowSize = m_app.ui().textSize(20.0f);
    const unsigned hintSize = m_app.ui().textSize(15.0f);
    const float lineHeight = font != nullptr ? font->getLineSpacing(rowSize) : 24.0f;
    const float rowHeight = lineHeight + 14.0f * scale;
    const float titleHeight = font != nullptr ? font->getLineSpacing(titleSize) : 0.0f;
    const float hintHeight = font != nullptr ? font->getLineSpacing(hintSize) : 0.0f;
    const float pad = 20.0f * scale;
    const float width = std::min(window.x - 20.0f, 620.0f * scale);

    // As many rows as fit; the list scrolls to keep the chosen row in view.
    const std::size_t count = rowIds().size();
    const float chrome = titleHeight + hintHeight + 3.0f * pad;
    const auto fitting = static_cast<std::size_t>(
        std::clamp(std::floor((window.y - 20.0f - chrome) / rowHeight), 1.0f, static_cast<float>(count)));
    if (m_selected < m_first)
        m_first = m_selected;
    if (m_selected >= m_first + fitting)
        m_first = m_selected + 1 - fitting;
    m_first = std::min(m_first, count - fitting);
    const float height = chrome + static_cast<float>(fitting) * rowHeight;
    const sf::FloatRect card(0.5f * (window.x - width), std::max(10.0f, 0.5f * (window.y - height)), width, height);
    drawCard(target, card, scale, palette::kButtonOutline);

    float y = card.top + pad;
    if (font != nullptr)
        drawLabel(target, *font, utf8("Settings"), {card.left + 0.5f * width, y}, titleSize, palette::kText,
                  Align::Centre);
    y += titleHeight + 0.5f * pad;
    m_rects.assign(count, sf::FloatRect());
    for (std::size_t i = m_first; i < m_first + fitting; ++i)
    {
        const sf::FloatRect rect(card.left + pad, y, width - 2.0f * pad, rowHeight - 4.0f * scale);
        m_rects[i] = rect;
        sf::RectangleShape box({rect.width, rect.height});
        box.setPosition(rect.left, rect.top);
        box.setFillColor(i == m_selected ? palette::kButtonSelected : palette::kButton);
        box.setOutlineColor(i == m_selected ? palette::kStar : palette::kButtonOutline);
        box.setOutlineThickness((i == m_selected ? 2.0f : 1.0f) * scale);
        target.draw(box);
        if (font != nullptr)
        {
            const std::string& id = rowIds()[i];
            const float textTop = rect.top + 0.5f * (rect.height - lineHeight);
            if (id == "back")
                drawLabel(target, *font, utf8(labelOf(id)), {rect.left + 0.5f * rect.width, textTop}, rowSize,
                          palette::kText, Align::Centre);
            else
                drawLabel(target, *font, utf8(labelOf(id)), {rect.left + 12.0f * scale, textTop}, rowSize,
                          palette::kText);
            if (id != "back")
                drawLabel(target, *font, utf8("\u2039  " + valueText(id) + "  \u203A"),
                          {rect.left + rect.width - 12.0f * scale, textTop}, rowSize, palette::kStar, Align::Right);
        }
        y += rowHeight;
    }
    if (font != nullptr)
    {
        std::string hint = "\u2191\u2193 choose   \u2190\u2192 change   Esc back";
        if (fitting < count)
            hint += "   (" + std::to_string(m_first + 1) + "\u2013" + std::to_string(m_first + fitting) + " of " +
                    std::to_string(count) + ")";
        drawLabel(target, *font, utf8(hint), {card.left + 0.5f * width, y + 0.5f * pad}, hintSize, palette::kTextDim,
                  Align::Centre);
    }
}

} // namespace abalike::app
