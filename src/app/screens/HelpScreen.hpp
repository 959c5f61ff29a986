#pragma once

#include "shell/Screen.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Window/Keyboard.hpp>
#include <set>
#include <string>
#include <vector>

namespace abalike::app
{

class AppContext;

/// The help overlay (F1 or ? anywhere): every control, by keyboard, mouse and gamepad, from the one controls table.
/// It lays the table out as columns when they fit the window and as stacked rows when they do not (large text
/// scale, small window), over as many pages as it needs: Right, Tab or a click turn the page; any other key, or a
/// click on the last page, closes it.
class HelpScreen : public Screen
{
public:
    static constexpr std::string_view kName = kHelpScreenName;

    explicit HelpScreen(AppContext& app) : m_app(app) {}

    std::string_view name() const override { return kName; }
    bool isOverlay() const override { return true; }
    void handleEvent(const sf::Event& event) override;
    void draw(sf::RenderTarget& target) override;

private:
    /// One line of the card: a group heading or a control.
    struct Line
    {
        std::size_t row = 0; ///< index into controlTable()
        bool heading = false;
        float height = 0.0f;
    };
    /// The table cut into pages that fit the window's height; rowHeights holds each control's height.
    std::vector<std::vector<Line>> paginate(const sf::Font& font, float usableHeight,
                                            const std::vector<float>& rowHeights) const;
    void turnPage(int delta);

    AppContext& m_app;
    int m_page = 0;
    int m_pages = 1; ///< as last drawn
    /// Keys pressed while this screen was on top: it closes when one of them is released, so that a key that opened
    /// it does not close it on its release, and a '?' (a key press, its text and a release, often in one frame)
    /// closes it once by its text.
    std::set<sf::Keyboard::Key> m_pressed;
    /// It asked to be closed: every later event of that frame belongs to the screen under it, not to a second pop.
    bool m_closing = false;
    void close();
};

} // namespace abalike::app
