#pragma once

#include "play/PlayLayer.hpp"

#include <SFML/Graphics/Rect.hpp>
#include <SFML/Window/Keyboard.hpp>
#include <cstddef>
#include <optional>
#include <vector>

namespace abalike::app
{

/// The row of buttons at the top right of the play screen: every keyboard-only action of play gets a mouse way
/// (camera home, the teaching keys T, G, I, K, C, help and pause). A click presses the button's key through the app's
/// input path, so a button can never do something its key does not. Pointing at a button names its action.
class PlayToolbar : public PlayLayer
{
public:
    /// One button: what it shows, the action it names and the key it presses.
    struct Button
    {
        const char* label; ///< text on the button; "" for the pause symbol
        const char* action;
        sf::Keyboard::Key key;
        bool held = false; ///< the key is down while the button is held (fast-forward), not tapped on release
    };

    std::string_view name() const override { return "toolbar"; }
    bool handleEvent(const sf::Event& event, PlayView& view) override;
    void drawScreen(sf::RenderTarget& target, PlayView& view) override;

    /// The buttons, left to right.
    static const std::vector<Button>& buttons();
    /// Where each button sits in a window of this size at this button scale.
    /// The buttons this run shows (the wording decides on the integrator tools).
    static std::vector<const Button*> shown(const AppContext& app);
    static std::vector<sf::FloatRect> layout(const AppContext& app, sf::Vector2u windowSize, float buttonScale);
    /// The toolbar's bottom edge in window pixels: panels in the top right start below it.
    static float bottomPx(float buttonScale);
    /// How large the buttons are drawn: with the window and the text scale, but at most 125 % of the window's own
    /// scale, so that at a 200 % text scale the row still fits beside the aim readout (tooltips take the full scale).
    static float buttonScale(const AppContext& app);
    /// How much of the top right the toolbar takes, from its left edge to the window's right (pixels).
    static float reservedWidthPx(const AppContext& app, sf::Vector2u windowSize);

private:
    std::optional<std::size_t> buttonAt(sf::Vector2f pixel, PlayView& view) const;

    std::optional<std::size_t> m_hover;
    std::optional<std::size_t> m_pressed;
};

} // namespace abalike::app
