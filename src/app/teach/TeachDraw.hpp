#pragma once

#include "render/Look.hpp"
#include "render/Mesh.hpp"

#include <SFML/Graphics/Color.hpp>
#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/Rect.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace abalike::app
{

/// Colours of the teaching aids: one per quantity, the same in every panel and arrow.
namespace teach
{
inline const sf::Color kVelocity(40, 200, 255);
inline const sf::Color kAcceleration(255, 80, 200);
inline const sf::Color kGravity(255, 200, 40);
inline const sf::Color kDrag(255, 110, 60);
inline const sf::Color kWind(120, 230, 140);
inline const sf::Color kKinetic(40, 200, 255);
inline const sf::Color kPotential(140, 120, 255);
inline const sf::Color kTotal(240, 240, 240);
inline const sf::Color kLoss(255, 110, 60);
inline const sf::Color& kPanel = activeLook().teachPanel;
inline const sf::Color& kPanelEdge = activeLook().teachPanelEdge;
inline const sf::Color kComparison(255, 70, 70);
} // namespace teach

/// An arrow from `from` to `to` (pixels) with a head in proportion to the width; nothing if shorter than a pixel.
/// With rim > 0, a dark rim of that width around it first, so that crossing arrows stay apart.
void addArrow(Mesh& mesh, sf::Vector2f from, sf::Vector2f to, float width, sf::Color colour, float rim = 0.0f);

/// A rectangle with an edge: the background of every teaching panel. `name` says which panel it is in the record of
/// a frame's layout (ScreenRegions).
void drawTeachPanel(sf::RenderTarget& target, sf::FloatRect rect, float scale, std::string_view name);

/// Whether a panel would lie inside the window and clear of every panel drawn before it this frame (ScreenRegions):
/// a column's panel with no such room shrinks to a one-line summary or is left out, never drawn over the others or
/// off the window.
bool panelHasRoom(const sf::RenderTarget& target, const sf::FloatRect& rect);

/// Whether the whole of a column's panel called `name` may be drawn at `rect`: it has room (panelHasRoom) and covers
/// nothing that must stay in view this frame (ScreenRegions' keepInView: the slingshot, the flying bird, live pigs).
/// One that would cover them is marked shrunk and takes its summary until the next aim (forgetShrunkPanels), so that it
/// does not flick between its two forms while the camera and the bird move under it.
bool fullPanelFits(const sf::RenderTarget& target, const sf::FloatRect& rect, std::string_view name);

/// Whether a panel at `rect` would cover something that must stay in view this frame (ScreenRegions' keepInView);
/// without `flyingBird`, only what stays put while the camera does (the slingshot, the pigs); without `slingshot`, all
/// but the slingshot with the bird it holds (a card beside it while aiming leaves the band in view).
bool coversKeptInView(const sf::FloatRect& rect, bool flyingBird = true, bool slingshot = true);

/// A panel's one-line summary, for where the whole panel has no room: `text` on one line (cut at a word with an
/// ellipsis to fit the window), its top corner at `corner` (the top-right one when `fromRight`). Drawn only where it
/// has room (panelHasRoom) and covers nothing that must stay in view (once it would have covered the slingshot, the
/// landing point or a live pig, it stays out until the next aim; while the flying bird passes under it, that long);
/// returns its bounds, empty when left out too. `name` is its name in ScreenRegions.
sf::FloatRect drawPanelSummary(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f corner, bool fromRight,
                               const std::string& text, unsigned rowSize, float scale, std::string_view name);

/// One row of a text panel: a label on the left, a value on the right, a colour swatch when set.
struct PanelRow
{
    std::string label;
    std::string value;
    sf::Color swatch = sf::Color::Transparent;
    bool heading = false; ///< drawn in the heading colour, without a value
};

/// A small panel of rows with a title, laid out by its widest row.
class TextPanel
{
public:
    TextPanel(std::string title, std::vector<PanelRow> rows) : m_title(std::move(title)), m_rows(std::move(rows)) {}

    /// Size it will take at these text sizes.
    sf::Vector2f measure(const sf::Font& font, unsigned titleSize, unsigned rowSize, float scale) const;
    /// Draws it with its top-left corner at `at`; returns its bounds.
    sf::FloatRect draw(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f at, unsigned titleSize,
                       unsigned rowSize, float scale) const;

private:
    std::string m_title;
    std::vector<PanelRow> m_rows;
};

/// Places short labels near points without covering each other: a label that would overlap an earlier one moves a
/// line down, up, two down or two up.
class LabelPlacer
{
public:
    /// Draws `text` with its left edge at x (right edge when alignRight) centred on y, moved off earlier labels.
    void draw(sf::RenderTarget& target, const sf::Font& font, const std::string& text, sf::Vector2f at, bool alignRight,
              unsigned size, sf::Color colour);

private:
    std::vector<sf::FloatRect> m_placed;
};

/// A number with a fixed count of decimals and a unit, e.g. "12.3 m/s".
std::string withUnit(double value, int decimals, const char* unit);

} // namespace abalike::app
