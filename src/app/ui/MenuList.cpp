#include "ui/MenuList.hpp"

#include "render/Label.hpp"
#include "render/Palette.hpp"

#include <SFML/Graphics/RectangleShape.hpp>

namespace abalike::app
{

void MenuList::setItems(std::vector<MenuItem> items)
{
    m_items = std::move(items);
    m_rects.clear();
    m_pressed.reset();
    m_selected = 0;
    if (!m_items.empty() && !m_items[0].enabled)
        move(1);
}

void MenuList::select(const std::string& id)
{
    for (std::size_t i = 0; i < m_items.size(); ++i)
        if (m_items[i].id == id && m_items[i].enabled)
            m_selected = i;
}

void MenuList::move(int direction)
{
    if (m_items.empty())
        return;
    const auto count = static_cast<int>(m_items.size());
    int index = static_cast<int>(m_selected);
    for (int tries = 0; tries < count; ++tries)
    {
        index = (index + direction + count) % count;
        if (m_items[static_cast<std::size_t>(index)].enabled)
        {
            m_selected = static_cast<std::size_t>(index);
            return;
        }
    }
}

std::optional<std::size_t> MenuList::itemAt(int x, int y) const
{
    for (std::size_t i = 0; i < m_rects.size() && i < m_items.size(); ++i)
        if (m_items[i].enabled && m_rects[i].contains(static_cast<float>(x), static_cast<float>(y)))
            return i;
    return std::nullopt;
}

std::optional<std::string> MenuList::handleEvent(const sf::Event& event)
{
    if (m_items.empty())
        return std::nullopt;
    switch (event.type)
    {
    case sf::Event::KeyPressed:
        switch (event.key.code)
        {
        case sf::Keyboard::Up:
        case sf::Keyboard::W:
            move(-1);
            return std::nullopt;
        case sf::Keyboard::Down:
        case sf::Keyboard::S:
        case sf::Keyboard::Tab:
            move(event.key.shift ? -1 : 1);
            return std::nullopt;
        case sf::Keyboard::Enter:
        case sf::Keyboard::Space:
            if (m_items[m_selected].enabled)
                return m_items[m_selected].id;
            return std::nullopt;
        default:
            return std::nullopt;
        }
    case sf::Event::MouseMoved:
        if (const std::optional<std::size_t> hit = itemAt(event.mouseMove.x, event.mouseMove.y))
            m_selected = *hit;
        return std::nullopt;
    case sf::Event::MouseButtonPressed:
        if (event.mouseButton.button == sf::Mouse::Left)
            m_pressed = itemAt(event.mouseButton.x, event.mouseButton.y);
        return std::nullopt;
    case sf::Event::MouseButtonReleased:
    {
        if (event.mouseButton.button != sf::Mouse::Left)
            return std::nullopt;
        // A click is a press and a release on the same button, as on every desktop.
        const std::optional<std::size_t> hit = itemAt(event.mouseButton.x, event.mouseButton.y);
        const bool clicked = hit && m_pressed == hit;
        m_pressed.reset();
        if (!clicked)
            return std::nullopt;
        m_selected = *hit;
        return m_items[*hit].id;
    }
    default:
        return std::nullopt;
    }
}

float MenuList::draw(sf::RenderTarget& target, const sf::Font* font, float centreX, float top, float width,
                     unsigned textSize, float scale)
{
    const float lineHeight = font != nullptr ? font->getLineSpacing(textSize) : static_cast<float>(textSize);
    const float height = lineHeight + 14.0f * scale;
    const float gap = 8.0f * scale;
    // Every button is as wide as the widest label needs (the title's "Learn: lessons, tutorial, physics" ran past
    // its button), within the window.
    if (font != nullptr)
        for (const MenuItem& item : m_items)
            width = std::max(width, measureText(*font, utf8(item.label), textSize).x + 32.0f * scale);
    width = std::min(width, static_cast<float>(target.getSize().x) - 16.0f * scale);
    m_rects.assign(m_items.size(), {});
    float y = top;
    for (std::size_t i = 0; i < m_items.size(); ++i)
    {
        const bool selected = i == m_selected && m_items[i].enabled;
        const sf::FloatRect rect(centreX - 0.5f * width, y, width, height);
        m_rects[i] = rect;
        sf::RectangleShape button({rect.width, rect.height});
        button.setPosition(rect.left, rect.top);
        button.setFillColor(selected ? palette::kButtonSelected : palette::kButton);
        button.setOutlineThickness(selected ? 3.0f * scale : 1.5f * scale);
        button.setOutlineColor(selected ? palette::kStar : palette::kButtonOutline);
        target.draw(button);
        if (font != nullptr)
            drawLabel(target, *font, utf8(m_items[i].label), {centreX, y + 0.5f * (height - lineHeight)}, textSize,
                      m_items[i].enabled ? palette::kText : palette::kTextDisabled, Align::Centre);
        y += height + gap;
    }
    return y - gap;
}

} // namespace abalike::app
