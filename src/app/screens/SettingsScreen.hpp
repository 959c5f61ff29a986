#pragma once

#include "shell/Screen.hpp"

#include <SFML/Graphics/Rect.hpp>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

class AppContext;

/// The settings (from the title and the pause menu): music and effects volume, mute, window size and full screen,
/// text size, colours (standard or colour-blind safe), high contrast, reduced motion and the teaching overlay. Every
/// change applies at once and is saved (App::updateSettings; never in a scripted run). Keyboard: Up/Down or Tab
/// choose, Left/Right change, Enter or Space step a value on, Esc goes back. Mouse: point at a row, click the left
/// or right half of its value to step it down or up; a right click goes back. Rows scroll when they do not fit.
class SettingsScreen : public Screen
{
public:
    static constexpr std::string_view kName = "settings";

    explicit SettingsScreen(AppContext& app) : m_app(app) {}

    std::string_view name() const override { return kName; }
    bool isOverlay() const override { return true; }
    void handleEvent(const sf::Event& event) override;
    void draw(sf::RenderTarget& target) override;

    /// The rows, top to bottom (stable ids, for tests).
    static const std::vector<std::string>& rowIds();
    /// What a row shows for the current settings.
    std::string valueText(const std::string& id) const;
    /// Steps a row's value down (-1) or up (+1); a switch flips either way.
    void change(const std::string& id, int direction);

private:
    void move(int direction);
    std::optional<std::size_t> rowAt(sf::Vector2f pixel) const;

    AppContext& m_app;
    std::size_t m_selected = 0;
    std::size_t m_first = 0;            ///< first row shown (the list scrolls at large text sizes)
    std::vector<sf::FloatRect> m_rects; ///< where each shown row was drawn, by row index; empty rect: not shown
};

} // namespace abalike::app
