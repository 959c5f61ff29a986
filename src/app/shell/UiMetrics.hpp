#pragma once

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderWindow.hpp>

namespace abalike::app
{

class PlayerSettings;

/// What drawing needs to know of the window: its size, the font, and how large text and panels are drawn (the
/// window's size against 1280x720 times the player's text scale).
class UiMetrics
{
public:
    UiMetrics(sf::RenderWindow& window, const sf::Font* font, const PlayerSettings& settings)
        : m_window(window), m_font(font), m_settings(settings)
    {
    }

    /// Null when no font could be loaded; screens then draw without text.
    const sf::Font* font() const { return m_font; }
    sf::Vector2u windowSize() const { return m_window.getSize(); }
    /// UI size multiplier: the window's size against 1280x720 times the player's text scale.
    float scale() const;
    /// Point size for UI text of a nominal size at 1280x720 and 100 % text scale.
    unsigned textSize(float nominal) const;
    /// The window itself, for the editor's Dear ImGui panels, which draw into it through their own bridge.
    sf::RenderWindow& window() const { return m_window; }

private:
    sf::RenderWindow& m_window;
    const sf::Font* m_font;
    const PlayerSettings& m_settings;
};

} // namespace abalike::app
