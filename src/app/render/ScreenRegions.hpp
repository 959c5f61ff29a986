#pragma once

#include <SFML/Graphics/Rect.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace abalike::app
{

/// A panel drawn over the world, where it was drawn (window pixels).
struct ScreenRegion
{
    std::string name;
    sf::FloatRect rect;
};

/// While set, every panel drawn over the world (HUD, toolbar, aim readout, teaching panels, guides, feedback,
/// labels, banners, notices) records its rectangle here: the trace's record of a frame's layout, and what the
/// layout test checks.
void setScreenRegionSink(std::vector<ScreenRegion>* sink);

/// Records one panel when a sink is set; panels call it where they draw their background.
void recordScreenRegion(std::string_view name, const sf::FloatRect& rect);

/// Pairs of regions (indices) that overlap by more than `tolerancePx` both ways.
std::vector<std::pair<std::size_t, std::size_t>> overlappingRegions(const std::vector<ScreenRegion>& regions,
                                                                    float tolerancePx = 1.0f);

} // namespace abalike::app
