#pragma once

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/Rect.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <string>
#include <vector>

namespace abalike::app
{

/// Live reload's message over the scene: the problems of an invalid edit of the level file, while the last good
/// version keeps playing. Folded (the default) it is one line, the heading and how many problems, so the level stays
/// in view; B or a click on it opens it to every problem in whole lines. Draws nothing without a font or problems.
class ReloadNotice
{
public:
    explicit ReloadNotice(const sf::Font* font) : m_font(font) {}

    /// lines: one FILE:LINE:COL problem each; heading: the sentence above them (the default: an edit that did not
    /// load).
    void draw(sf::RenderTarget& target, sf::Vector2u size, const std::vector<std::string>& lines,
              float textScale = 1.0f, const std::string& heading = kEditDidNotLoad) const;

    /// How far up from the window's bottom it reaches when drawn (0 when it draws nothing): the play screen keeps
    /// the ground above it, so that the banner never covers the birds waiting by the slingshot.
    float reach(sf::Vector2u size, const std::vector<std::string>& lines, float textScale = 1.0f,
                const std::string& heading = kEditDidNotLoad) const;

    static constexpr const char* kEditDidNotLoad =
        "The level file has errors; still playing the last good version. Save a fix to reload.";
    static constexpr const char* kDoesNotStand =
        "This level does not stand as built: bodies move with no shot fired. Save a fix to reload.";

    /// Opens or folds it (key B).
    void toggle() { m_expanded = !m_expanded; }
    bool expanded() const { return m_expanded; }
    /// A click at (x, y) on the banner as last drawn opens or folds it; true when it did.
    bool handleClick(float x, float y);

private:
    /// Its lines as wrapped for the window, and its size.
    struct Layout
    {
        std::vector<std::string> title;
        std::vector<std::string> body;
        std::size_t hidden = 0;                      ///< problems left out for room
        float pad = 0.0f, height = 0.0f, top = 0.0f; ///< pixels
        unsigned titleSize = 0, lineSize = 0;        ///< character sizes
    };
    Layout layout(sf::Vector2u size, const std::vector<std::string>& lines, float textScale,
                  const std::string& heading) const;

    const sf::Font* m_font;
    bool m_expanded = false;
    mutable sf::FloatRect m_lastRect; ///< where the last draw put it (empty when nothing was drawn)
};

} // namespace abalike::app
