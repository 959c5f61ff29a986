#pragma once

#include "screens/PlayLayer.hpp"

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
    bool m_shotOver = false; ///< the next bird is ready: the card may leave a spot the world now fills
    std::size_t m_shotsSeen = 0;
    bool m_done = false;
    std::optional<std::pair<double, double>> m_firstAim; ///< angle and speed when the next bird became ready
    std::vector<std::string> m_sentences;
};

} // namespace abalike::app
