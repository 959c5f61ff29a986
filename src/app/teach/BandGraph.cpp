#include "teach/BandGraph.hpp"

#include "render/Label.hpp"
#include "render/Mesh.hpp"
#include "render/Palette.hpp"
#include "render/TextFormat.hpp"
#include "teach/TeachDraw.hpp"

#include <algorithm>

namespace abalike::app
{

namespace
{
const sf::Color kLine(240, 240, 240);
const sf::Color kArea(255, 200, 40, 150);
const sf::Color kAxis(190, 196, 210);

struct GraphMetrics
{
    float pad = 0.0f;
    float titleHeight = 0.0f;
    float rowHeight = 0.0f;
    float plotWidth = 0.0f;
    float plotHeight = 0.0f;
    float axisLabelWidth = 0.0f; ///< room left of the plot for the force ticks
};

GraphMetrics metricsFor(const sf::Font& font, unsigned titleSize, unsigned rowSize, float scale)
{
    GraphMetrics m;
    m.pad = 8.0f * scale;
    m.titleHeight = font.getLineSpacing(titleSize) * 1.1f;
    m.rowHeight = font.getLineSpacing(rowSize);
    m.plotWidth = 170.0f * scale;
    m.plotHeight = 96.0f * scale;
    m.axisLabelWidth = measureText(font, utf8("00000 N"), rowSize).x + 4.0f * scale;
    // Wide enough for the energy line under the plot.
    const float energyLine = measureText(font, utf8("area = E = \u00BD F x = 00000 J  (k = 00000 N/m)"), rowSize).x;
    m.plotWidth = std::max(m.plotWidth, energyLine - m.axisLabelWidth - m.pad);
    return m;
}
} // namespace

sf::Vector2f BandGraph::measure(const sf::Font& font, unsigned titleSize, unsigned rowSize, float scale)
{
    const GraphMetrics m = metricsFor(font, titleSize, rowSize, scale);
    // Title, plot, the pull axis's ticks, then the energy line.
    return {m.axisLabelWidth + m.plotWidth + 3.0f * m.pad,
            m.titleHeight + m.plotHeight + 2.0f * m.rowHeight + 2.5f * m.pad};
}

sf::FloatRect BandGraph::draw(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topRight,
                              const AimReadout& aim, unsigned titleSize, unsigned rowSize, float scale)
{
    if (aim.maxPullM <= 0.0 || aim.maxForceN <= 0.0)
        return {};
    const GraphMetrics m = metricsFor(font, titleSize, rowSize, scale);
    const sf::Vector2f size = measure(font, titleSize, rowSize, scale);
    const sf::FloatRect rect(topRight.x - size.x, topRight.y, size.x, size.y);
    drawTeachPanel(target, rect, scale, "aim graph");
    drawLabel(target, font, utf8("Band: force F against pull x"), {rect.left + m.pad, rect.top + m.pad}, titleSize,
              palette::kText);

    // Plot frame: origin at the bottom left; x is the pull (0 to the full pull), y the force (0 to F at full pull).
    const float left = rect.left + m.pad + m.axisLabelWidth;
    const float top = rect.top + m.pad + m.titleHeight;
    const float bottom = top + m.plotHeight;
    const float right = left + m.plotWidth;
    const auto at = [&](double pullM, double forceN)
    {
        return sf::Vector2f(left + static_cast<float>(pullM / aim.maxPullM) * m.plotWidth,
                            bottom - static_cast<float>(forceN / aim.maxForceN) * m.plotHeight);
    };
    Mesh mesh;
    const float line = std::max(1.0f, 1.5f * scale);
    // The shaded triangle under the line up to the current pull is E = 1/2 F x.
    if (aim.pull.pullM > 0.0)
        mesh.addTriangle(at(0.0, 0.0), at(aim.pull.pullM, 0.0), at(aim.pull.pullM, aim.pull.forceN), kArea);
    mesh.addLine({left, bottom}, {right + 4.0f * scale, bottom}, line, kAxis);
    mesh.addLine({left, bottom}, {left, top - 4.0f * scale}, line, kAxis);
    mesh.addLine(at(0.0, 0.0), at(aim.maxPullM, aim.maxForceN), 2.0f * line, kLine);
    const sf::Vector2f now = at(aim.pull.pullM, aim.pull.forceN);
    mesh.addLine(now, {now.x, bottom}, line, kArea);
    mesh.addCircle(now, 4.0f * scale, kLine, 16);
    mesh.draw(target);

    const auto dim = palette::kTextDim;
    drawLabel(target, font, utf8(formatFixed(aim.maxForceN, 0) + " N"), {left - 4.0f * scale, top - 0.5f * m.rowHeight},
              rowSize, dim, Align::Right);
    drawLabel(target, font, utf8("0"), {left, bottom + 2.0f * scale}, rowSize, dim, Align::Centre);
    drawLabel(target, font, utf8("pull x"), {0.5f * (left + right), bottom + 2.0f * scale}, rowSize, dim,
              Align::Centre);
    drawLabel(target, font, utf8(formatFixed(aim.maxPullM, 1) + " m"), {right, bottom + 2.0f * scale}, rowSize, dim,
              Align::Right);
    drawLabel(target, font,
              utf8("area = E = \u00BD F x = " + formatFixed(aim.pull.energyJ, 0) +
                   " J  (k = " + formatFixed(aim.maxForceN / aim.maxPullM, 0) + " N/m)"),
              {rect.left + m.pad, bottom + 2.0f * scale + m.rowHeight}, rowSize, kArea);
    return rect;
}

} // namespace abalike::app
