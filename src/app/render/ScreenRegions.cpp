#include "render/ScreenRegions.hpp"

#include <algorithm>

namespace abalike::app
{

namespace
{
std::vector<ScreenRegion>* g_sink = nullptr;
} // namespace

void setScreenRegionSink(std::vector<ScreenRegion>* sink)
{
    g_sink = sink;
}

void recordScreenRegion(std::string_view name, const sf::FloatRect& rect)
{
    if (g_sink != nullptr && rect.width > 0.0f && rect.height > 0.0f)
        g_sink->push_back({std::string(name), rect});
}

std::vector<std::pair<std::size_t, std::size_t>> overlappingRegions(const std::vector<ScreenRegion>& regions,
                                                                    float tolerancePx)
{
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t i = 0; i < regions.size(); ++i)
        for (std::size_t j = i + 1; j < regions.size(); ++j)
        {
            const sf::FloatRect& a = regions[i].rect;
            const sf::FloatRect& b = regions[j].rect;
            const float overlapX = std::min(a.left + a.width, b.left + b.width) - std::max(a.left, b.left);
            const float overlapY = std::min(a.top + a.height, b.top + b.height) - std::max(a.top, b.top);
            if (overlapX > tolerancePx && overlapY > tolerancePx)
                pairs.emplace_back(i, j);
        }
    return pairs;
}

} // namespace abalike::app
