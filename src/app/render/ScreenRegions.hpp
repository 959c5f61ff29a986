#pragma once

#include <SFML/Graphics/Rect.hpp>
#include <optional>
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

/// While set, the play screen writes here what its panels should leave visible in the frame it draws (the slingshot,
/// the flying bird, live pigs: keepVisibleBoxes in render/LabelPlacement): the trace's record for the layout tests.
void setKeepVisibleSink(std::vector<ScreenRegion>* sink);
std::vector<ScreenRegion>* keepVisibleSink();

/// False while a frame is only laid out, not drawn (the layout tests, FrameObserver::layoutEvery): every panel still
/// finds its place and measures its text, but labels and meshes skip their draw calls and the world's picture is left
/// out.
void setDrawingPixels(bool drawing);
bool drawingPixels();

/// Starts a frame's layout: the panels recorded from now on are what later panels of the frame keep clear of.
/// What must stay in view (setKeepInView) is cleared with it.
void beginScreenLayout();

/// What the large panels drawn from now on in this frame must leave in view (window pixels, named: the slingshot, the
/// flying bird, live pigs); a panel with no room clear of them shrinks to its summary (teach/TeachDraw's
/// fullPanelFits).
void setKeepInView(std::vector<ScreenRegion> things);
const std::vector<ScreenRegion>& keepInView();

/// The panels that shrank to their summary because they would have covered what must stay in view: they stay
/// summaries until forgetShrunkPanels() (the next aim), so that a panel does not flick between its two forms as the
/// camera and the bird move under it. A panel that shrinks row by row (a lesson's step) keeps the rows it was left.
bool panelShrunk(std::string_view name);
void markPanelShrunk(std::string_view name, std::size_t rowsKept = 0);
/// The rows a shrunk panel kept; none when it has not shrunk since the last aim.
std::optional<std::size_t> shrunkRows(std::string_view name);
void forgetShrunkPanels();

/// The panels drawn so far in this frame's layout.
const std::vector<ScreenRegion>& screenLayout();

/// The highest top edge, at or below `top`, for a panel of this width and height at `left` that overlaps no panel
/// drawn so far this frame (each overlap moves it under that panel, `gap` apart).
float firstFreeTop(float left, float width, float top, float height, float gap);

/// The rectangles of these regions, for the placement helpers that take plain rectangles.
std::vector<sf::FloatRect> rectsOf(const std::vector<ScreenRegion>& regions);

/// Pairs of regions (indices) that overlap by more than `tolerancePx` both ways.
std::vector<std::pair<std::size_t, std::size_t>> overlappingRegions(const std::vector<ScreenRegion>& regions,
                                                                    float tolerancePx = 1.0f);

} // namespace abalike::app
