#include "render/ScreenRegions.hpp"

#include <algorithm>

namespace abalike::app
{

namespace
{
bool g_drawingPixels = true;
std::vector<ScreenRegion>* g_sink = nullptr;
std::vector<ScreenRegion>* g_keepVisibleSink = nullptr;
std::vector<ScreenRegion> g_frame;
std::vector<ScreenRegion> g_keepInView;
std::vector<std::pair<std::string, std::size_t>> g_shrunk; ///< name, rows kept
} // namespace

void setDrawingPixels(bool drawing)
{
    g_drawingPixels = drawing;
}

bool drawingPixels()
{
    return g_drawingPixels;
}

void beginScreenLayout()
{
    g_frame.clear();
    g_keepInView.clear();
}

void setKeepInView(std::vector<ScreenRegion> things)
{
    g_keepInView = std::move(things);
}

const std::vector<ScreenRegion>& keepInView()
{
    return g_keepInView;
}

namespace
{
std::vector<std::pair<std::string, std::size_t>>::iterator findShrunk(std::string_view name)
{
    return std::find_if(g_shrunk.begin(), g_shrunk.end(), [name](const auto& s) { return s.first == name; });
}
} // namespace

std::optional<std::size_t> shrunkRows(std::string_view name)
{
    const auto found = findShrunk(name);
    if (found == g_shrunk.end())
        return std::nullopt;
    return found->second;
}

bool panelShrunk(std::string_view name)
{
    return shrunkRows(name).has_value();
}

void markPanelShrunk(std::string_view name, std::size_t rowsKept)
{
    if (const auto found = findShrunk(name); found != g_shrunk.end())
        found->second = std::min(found->second, rowsKept);
    else
        g_shrunk.emplace_back(name, rowsKept);
}

void forgetShrunkPanels()
{
    g_shrunk.clear();
}

const std::vector<ScreenRegion>& screenLayout()
{
    return g_frame;
}

float firstFreeTop(float left, float width, float top, float height, float gap)
{
    // Each pass moves the panel under the first panel it overlaps; y only grows, so this ends.
    for (bool moved = true; moved;)
    {
        moved = false;
        for (const ScreenRegion& region : g_frame)
        {
            const sf::FloatRect& r = region.rect;
            const bool acrossX = left < r.left + r.width && r.left < left + width;
            const bool acrossY = top < r.top + r.height && r.top < top + height;
            if (acrossX && acrossY)
            {
                top = r.top + r.height + gap;
                moved = true;
            }
        }
    }
    return top;
}

void setScreenRegionSink(std::vector<ScreenRegion>* sink)
{
    g_sink = sink;
}

void setKeepVisibleSink(std::vector<ScreenRegion>* sink)
{
    g_keepVisibleSink = sink;
}

std::vector<ScreenRegion>* keepVisibleSink()
{
    return g_keepVisibleSink;
}

void recordScreenRegion(std::string_view name, const sf::FloatRect& rect)
{
    if (rect.width <= 0.0f || rect.height <= 0.0f)
        return;
    g_frame.push_back({std::string(name), rect});
    if (g_sink != nullptr)
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

std::vector<sf::FloatRect> rectsOf(const std::vector<ScreenRegion>& regions)
{
    std::vector<sf::FloatRect> rects;
    rects.reserve(regions.size());
    for (const ScreenRegion& region : regions)
        rects.push_back(region.rect);
    return rects;
}

} // namespace abalike::app
