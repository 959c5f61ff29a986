#include "play/PlayToolbar.hpp"

#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "render/ScreenRegions.hpp"
#include "shell/AppContext.hpp"
#include "shell/Navigator.hpp"
#include "shell/PlayerSettings.hpp"
#include "shell/UiMetrics.hpp"

#include <SFML/Graphics/RectangleShape.hpp>
#include <algorithm>
#include <cmath>

namespace abalike::app
{

namespace
{
constexpr float kMarginPx = 10.0f;
constexpr float kSizePx = 34.0f;
constexpr float kGapPx = 6.0f;
constexpr float kMaxButtonGrowth = 1.25f;

sf::Event keyEvent(sf::Keyboard::Key key, bool pressed)
{
    sf::Event event{};
    event.type = pressed ? sf::Event::KeyPressed : sf::Event::KeyReleased;
    event.key.code = key;
    return event;
}

void drawRect(sf::RenderTarget& target, sf::FloatRect rect, sf::Color fill)
{
    sf::RectangleShape shape({rect.width, rect.height});
    shape.setPosition(rect.left, rect.top);
    shape.setFillColor(fill);
    target.draw(shape);
}
} // namespace

const std::vector<PlayToolbar::Button>& PlayToolbar::buttons()
{
    static const std::vector<Button> list{
        {"\u2302", "Camera back to the level (Home)", sf::Keyboard::Home},
        {"T", "Teaching overlay (T)", sf::Keyboard::T},
        {"G", "Range-by-angle chart (G)", sf::Keyboard::G},
        {"I", "Integrator comparison (I)", sf::Keyboard::I},
        {"K", "RK4 walkthrough (K)", sf::Keyboard::K},
        {"C", "Clear the kept paths (C)", sf::Keyboard::C},
        {"V", "Velocity components vx, vy (V)", sf::Keyboard::V},
        {"Z", "Slow motion: 1, \u00BD, \u00BC of real time (Z)", sf::Keyboard::Z},
        {"\u00BB", "Hold: fast-forward the flight, 3\u00D7 (hold F)", sf::Keyboard::F, true},
        {"\u21A7", "Export the shots as CSV (E)", sf::Keyboard::E},
        {"?", "Help: every control (F1)", sf::Keyboard::F1},
        {"", "Pause (Esc or P)", sf::Keyboard::P},
    };
    return list;
}

std::vector<const PlayToolbar::Button*> PlayToolbar::shown(const AppContext& app)
{
    // School wording leaves out the integrator tools (I and K), whose very names are the machinery.
    std::vector<const Button*> list;
    for (const Button& button : buttons())
        if (app.settings().universityWording() || (button.key != sf::Keyboard::I && button.key != sf::Keyboard::K))
            list.push_back(&button);
    return list;
}

std::vector<sf::FloatRect> PlayToolbar::layout(const AppContext& app, sf::Vector2u windowSize, float scale)
{
    const float size = kSizePx * scale;
    const float gap = kGapPx * scale;
    const std::size_t count = shown(app).size();
    float x = static_cast<float>(windowSize.x) - kMarginPx * scale - static_cast<float>(count) * (size + gap) + gap;
    std::vector<sf::FloatRect> rects;
    for (std::size_t i = 0; i < count; ++i, x += size + gap)
        rects.emplace_back(x, kMarginPx * scale, size, size);
    return rects;
}

float PlayToolbar::bottomPx(float buttonScale)
{
    return (kMarginPx + kSizePx) * buttonScale;
}

float PlayToolbar::buttonScale(const AppContext& app)
{
    const float textScale = static_cast<float>(app.settings().current().textScale);
    const float windowScale = app.ui().scale() / std::max(textScale, 1e-3f);
    return windowScale * std::min(textScale, kMaxButtonGrowth);
}

float PlayToolbar::reservedWidthPx(const AppContext& app, sf::Vector2u windowSize)
{
    const std::vector<sf::FloatRect> rects = layout(app, windowSize, buttonScale(app));
    return rects.empty() ? 0.0f : static_cast<float>(windowSize.x) - rects.front().left;
}

std::optional<std::size_t> PlayToolbar::buttonAt(sf::Vector2f pixel, PlayView& view) const
{
    const std::vector<sf::FloatRect> rects = layout(view.app(), view.app().ui().windowSize(), buttonScale(view.app()));
    for (std::size_t i = 0; i < rects.size(); ++i)
        if (rects[i].contains(pixel))
            return i;
    return std::nullopt;
}

bool PlayToolbar::handleEvent(const sf::Event& event, PlayView& view)
{
    switch (event.type)
    {
    case sf::Event::MouseMoved:
        m_hover = buttonAt({static_cast<float>(event.mouseMove.x), static_cast<float>(event.mouseMove.y)}, view);
        return false; // others still see where the pointer is
    case sf::Event::MouseButtonPressed:
        if (event.mouseButton.button != sf::Mouse::Left)
            return false;
        m_pressed = buttonAt({static_cast<float>(event.mouseButton.x), static_cast<float>(event.mouseButton.y)}, view);
        if (m_pressed && shown(view.app())[*m_pressed]->held)
            view.app().navigator().post(keyEvent(shown(view.app())[*m_pressed]->key, true));
        return m_pressed.has_value(); // a click on a button neither aims nor fires the ability
    case sf::Event::MouseButtonReleased:
    {
        if (event.mouseButton.button != sf::Mouse::Left || !m_pressed)
            return false;
        const std::optional<std::size_t> over =
            buttonAt({static_cast<float>(event.mouseButton.x), static_cast<float>(event.mouseButton.y)}, view);
        if (const Button& pressed = *shown(view.app())[*m_pressed]; pressed.held)
            view.app().navigator().post(keyEvent(pressed.key, false)); // let go anywhere: the key is up again
        else if (over == m_pressed)
        {
            const sf::Keyboard::Key key = shown(view.app())[*over]->key;
            view.app().navigator().post(keyEvent(key, true));
            view.app().navigator().post(keyEvent(key, false));
        }
        m_pressed.reset();
        return true;
    }
    default:
        return false;
    }
}

void PlayToolbar::drawScreen(sf::RenderTarget& target, PlayView& view)
{
    AppContext& app = view.app();
    const float scale = buttonScale(app);
    const std::vector<sf::FloatRect> rects = layout(app, target.getSize(), scale);
    const std::vector<const Button*> visible = shown(app);
    const sf::Font* font = app.ui().font();
    const auto textSize = static_cast<unsigned>(std::round(17.0f * scale));
    for (std::size_t i = 0; i < rects.size(); ++i)
    {
        const sf::FloatRect& rect = rects[i];
        recordScreenRegion("toolbar", rect);
        const bool lit = m_hover == i || m_pressed == i;
        sf::RectangleShape box({rect.width, rect.height});
        box.setPosition(rect.left, rect.top);
        box.setFillColor(lit ? palette::kButtonSelected : palette::kButton);
        box.setOutlineColor(palette::kButtonOutline);
        box.setOutlineThickness(1.5f * scale);
        target.draw(box);
        const Button& button = *visible[i];
        if (*button.label == '\0')
        {
            // The pause symbol: two bars.
            const float barW = 0.16f * rect.width;
            const float barH = 0.5f * rect.height;
            const float top = rect.top + 0.25f * rect.height;
            drawRect(target, {rect.left + 0.28f * rect.width, top, barW, barH}, palette::kText);
            drawRect(target, {rect.left + 0.56f * rect.width, top, barW, barH}, palette::kText);
        }
        else if (font != nullptr)
            // The slow-motion button shows the pace the world runs at now.
            drawLabel(target, *font, utf8(button.key == sf::Keyboard::Z ? view.slowMotion().label() : button.label),
                      {rect.left + 0.5f * rect.width, rect.top + 0.5f * (rect.height - font->getLineSpacing(textSize))},
                      textSize, palette::kText, Align::Centre);
    }
    if (m_hover && font != nullptr)
    {
        // The action under the pointer, right-aligned under the row, on a panel so it reads over any sky.
        const unsigned tipSize = app.ui().textSize(15.0f);
        const float tipScale = app.ui().scale();
        const sf::String tip = utf8(visible[std::min(*m_hover, visible.size() - 1)]->action);
        const sf::Vector2f extent = measureText(*font, tip, tipSize);
        const float pad = 6.0f * tipScale;
        const float right = rects.back().left + rects.back().width;
        const sf::FloatRect panel(right - extent.x - 2.0f * pad, bottomPx(scale) + pad, extent.x + 2.0f * pad,
                                  font->getLineSpacing(tipSize) + pad);
        recordScreenRegion("toolbar tip", panel);
        drawRect(target, panel, palette::kPanel);
        drawLabel(target, *font, tip, {panel.left + pad, panel.top + 0.5f * pad}, tipSize, palette::kText);
    }
}

} // namespace abalike::app
