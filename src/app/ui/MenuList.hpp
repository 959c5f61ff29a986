#pragma once

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/Rect.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Window/Event.hpp>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

/// One entry of a menu.
struct MenuItem
{
    std::string id;    ///< stable name for code and traces ("resume", "restart", ...)
    std::string label; ///< what the player reads
    bool enabled = true;
};

/// A vertical list of buttons driven by keyboard (Up/Down, Enter or Space) and mouse (hover, click) alike.
class MenuList
{
public:
    void setItems(std::vector<MenuItem> items);
    const std::vector<MenuItem>& items() const { return m_items; }

    /// Handles an event; returns the id of the item activated by it, if any.
    std::optional<std::string> handleEvent(const sf::Event& event);

    /// Draws the buttons centred on centreX from top, each `width` wide; remembers where, for the mouse.
    /// Returns the bottom edge.
    float draw(sf::RenderTarget& target, const sf::Font* font, float centreX, float top, float width, unsigned textSize,
               float scale);

    std::size_t selected() const { return m_selected; }
    void select(const std::string& id);

private:
    void move(int direction);
    std::optional<std::size_t> itemAt(int x, int y) const;

    std::vector<MenuItem> m_items;
    std::vector<sf::FloatRect> m_rects; ///< where each item was drawn last
    std::size_t m_selected = 0;
    std::optional<std::size_t> m_pressed; ///< the item a mouse press started on
};

} // namespace abalike::app
