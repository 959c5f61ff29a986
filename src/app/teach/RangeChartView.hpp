#pragma once

#include "play/PlayLayer.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <abalike/teach/RangeChart.hpp>
#include <optional>

namespace abalike::app
{

/// A small chart of range against launch angle for the bird in the slingshot, at the current launch speed, in this
/// level's gravity, air and wind, from the slingshot's height to the ground: the best angle marked, the current aim
/// highlighted. It follows the aim.
class RangeChartView
{
public:
    /// Recomputes when the bird, the speed or the level changed.
    void update(const GameSession& session, const std::optional<AimReadout>& aim);
    /// Draws it with its top-right corner at `topRight`; returns its bounds (empty when there is nothing to show).
    sf::FloatRect draw(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topRight, unsigned titleSize,
                       unsigned rowSize, float scale) const;

private:
    struct Key
    {
        std::string level;
        std::string bird;
        double speedMps = -1.0;
        bool operator==(const Key&) const = default;
    };
    Key m_key;
    std::optional<RangeChart> m_chart;
    RangeLaunch m_launch;
    std::optional<double> m_aimDeg;
    std::optional<double> m_aimRangeM;
};

} // namespace abalike::app
