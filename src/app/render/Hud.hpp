#pragma once

#include "render/AimReadout.hpp"
#include "render/Label.hpp"
#include <SFML/Graphics/Font.hpp>

#include <SFML/Graphics/RenderTarget.hpp>
#include <abalike/game/GameSession.hpp>
#include <abalike/save/Settings.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace abalike::app
{

/// Text over the scene while playing: level name, score, birds and pigs left, the air, the aim readout and
/// the level's hint. Draws nothing without a font.
class Hud
{
public:
    explicit Hud(const sf::Font* font) : m_font(font) {}

    /// textScale: the player's text size (1 to 2). reservedRightPx: the top right corner's width taken by the
    /// toolbar; the aim readout stays clear of it and of the status panel, moving under them when the top is full.
    /// Game mode shows the aim as the genre does (a power bar and the angle) and the air only when the wind blows;
    /// learn mode the band's numbers with units, how they follow from each other, and gravity and the air.
    /// levelLabel: what the status panel calls the level ("2-6", PlayView::levelLabel; empty: the title alone).
    /// keepClear: what no strip may cover (window pixels: live pigs, the flying bird, the last shot's landing point).
    /// A strip gives way to them: the aim readout and the ability prompt take the first of their places clear of them,
    /// the keys and the hint slide to the left or right end of their line, and a strip with no clear place (the
    /// status and the air have one) waits out of sight for that frame; the others keep their places.
    void draw(sf::RenderTarget& target, sf::Vector2u size, const GameSession& session,
              const std::optional<AimReadout>& aim, PlayMode mode, std::string_view levelLabel, float textScale = 1.0f,
              float reservedRightPx = 0.0f, std::span<const sf::FloatRect> keepClear = {}) const;

    /// How far up from the window's bottom the keys line and the level's hint reach (pixels), as draw lays them out
    /// at this text size: the camera keeps the ground line above them, so that at large text they cover no slingshot.
    float bottomTextHeight(sf::Vector2u size, const LevelDef& level, float textScale = 1.0f) const;

private:
    /// One of the lines at the bottom (the keys, the hint), wrapped to the window.
    struct BottomText
    {
        std::vector<std::string> lines;
        unsigned textSize;
        sf::Color colour;
        const char* name;
        TextKind kind;
    };
    /// The keys line, then the level's hint: drawn bottom up in that order.
    std::vector<BottomText> bottomText(sf::Vector2u size, float scale, const LevelDef& level) const;
    /// Where a strip of the top row may go (window pixels): between the status panel (`left`) and the toolbar
    /// (`right`), else at the left edge from `below` down to `lowest` (the keys and the hint); what it must leave in
    /// view.
    struct TopRow
    {
        sf::Vector2u size;
        float scale;
        float left;
        float right;
        float below;
        float lowest;
        std::span<const sf::FloatRect> keepClear;
        /// The first place for a strip of this size that leaves keepClear in view: centred in the window between
        /// the status panel and the toolbar if it fits there, else at either end of that room, else at the left edge
        /// from `below`, lower down by half its height at a time while it stays above `lowest` (a strip as wide as
        /// the window finds the gap between a tower's pigs). None: it waits out of sight for the frame.
        std::optional<sf::Vector2f> spot(sf::Vector2f stripSize) const;
    };
    /// Returns the panel's place, drawn or not (the strips under it keep their places either way).
    sf::FloatRect drawStatus(sf::RenderTarget& target, sf::Vector2u size, float scale, const GameSession& session,
                             std::string_view levelLabel, PlayMode mode,
                             std::span<const sf::FloatRect> keepClear) const;
    /// Returns the bottom edge of the panel's place (top when the level shows none).
    float drawEnvironment(sf::RenderTarget& target, float top, float scale, const LevelDef& level, PlayMode mode,
                          std::span<const sf::FloatRect> keepClear) const;
    /// Centred at the top between `left` and `right` if it fits there, else at the left from `below`.
    void drawAim(sf::RenderTarget& target, const TopRow& row, const AimReadout& aim) const;
    /// The genre's aim: a power bar filled to the pull and the angle, no units.
    void drawPowerBar(sf::RenderTarget& target, const TopRow& row, const AimReadout& aim) const;
    void drawAbilityPrompt(sf::RenderTarget& target, const TopRow& row, const GameSession& session) const;
    void drawHint(sf::RenderTarget& target, sf::Vector2u size, float scale, const LevelDef& level,
                  std::span<const sf::FloatRect> keepClear) const;

    /// The first hint with its {...} values filled, kept until the text, the air or the slingshot changes (a range
    /// in a hint costs a range chart, not something to pay every frame).
    const std::string& filledHint(const LevelDef& level) const;

    const sf::Font* m_font;
    mutable std::string m_hintSource;
    mutable std::string m_hintShown;
    mutable EnvironmentDef m_hintAir;
    mutable SlingshotDef m_hintSlingshot;
};

/// Text scale for a window: 1 at 1280x720.
float hudScale(sf::Vector2u size);

} // namespace abalike::app
