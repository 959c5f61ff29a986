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
    /// Draws the sentences centred above `bottom` (window pixels), wrapped to `maxWidth`; if the panel would cover
    /// any of the boxes in `avoid` (the structure on screen) and it would not at `top`, it goes there instead.
    void draw(sf::RenderTarget& target, const sf::Font& font, float bottom, float top,
              std::span<const sf::FloatRect> avoid, float maxWidth, unsigned rowSize, float scale) const;

private:
    std::size_t m_shotsSeen = 0;
    bool m_done = false;
    std::optional<std::pair<double, double>> m_firstAim; ///< angle and speed when the next bird became ready
    std::vector<std::string> m_sentences;
};

} // namespace abalike::app
