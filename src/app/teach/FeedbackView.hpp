#pragma once

#include "play/PlayLayer.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <abalike/game/GameSession.hpp>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace abalike::app
{

/// One or two sentences after every shot, with its real numbers (abalike::shotFeedback): shown from the bird's
/// first contact (or the end of its flight) until the next launch.
class FeedbackView
{
public:
    /// `aim`: the current aim while a bird waits; once the player changes it the sentences have been read.
    void update(const GameSession& session, const std::optional<AimReadout>& aim);
    void reset();
    const std::vector<std::string>& sentences() const { return m_sentences; }
    /// Draws the sentences wrapped to `maxWidth` on a card: above `bottom` (window pixels) in the middle, else at
    /// its left or right, else from `top` down under the panels already drawn this frame (ScreenRegions), the first
    /// spot inside the window clear of every panel and of the boxes of `avoid` (the structure on screen), else the
    /// one covering least of `keep` (the slingshot, the flying bird and the pigs: what the player must see), and of
    /// those the one covering least of `avoid`. With no such spot, the first sentence cut to one line in the same
    /// way; with none for that either, nothing. The spot is chosen once per shot's sentences, so the card stays put
    /// while the world moves; once the next bird is ready it leaves a spot over the world's boxes for one clear of
    /// them, or, when it covers the slingshot or a pig, for one clear of those, if any.
    void draw(sf::RenderTarget& target, const sf::Font& font, float bottom, float top,
              std::span<const sf::FloatRect> avoid, std::span<const sf::FloatRect> keep, float maxWidth,
              unsigned rowSize, float scale) const;

private:
    void drawCard(sf::RenderTarget& target, const sf::Font& font, const sf::FloatRect& rect,
                  const std::vector<std::string>& lines, unsigned rowSize, float scale) const;

    mutable std::optional<std::size_t> m_spot; ///< the candidate spot chosen for the current sentences
    mutable bool m_collapsed = false;          ///< that spot holds the one-line summary, not the whole card
    /// The next bird is ready, or the level is over: the card may leave a spot the world now fills.
    bool m_shotOver = false;
    /// The card left a spot during the shot because the camera had moved the slingshot, the bird or a pig under it:
    /// it does so once a shot, so that it never jumps to and fro while a structure collapses.
    mutable bool m_movedDuringShot = false;
    std::size_t m_shotsSeen = 0;
    bool m_done = false;
    std::optional<std::pair<double, double>> m_firstAim; ///< angle and speed when the next bird became ready
    std::vector<std::string> m_sentences;
    std::string m_summary; ///< the first sentence's gist, for the one-line card
};

} // namespace abalike::app
