#include "teach/RangeChartView.hpp"

#include "render/Label.hpp"
#include "render/Mesh.hpp"
#include "render/Palette.hpp"
#include "render/TextFormat.hpp"
#include "teach/TeachDraw.hpp"

#include <abalike/level/LevelFlight.hpp>
#include <algorithm>
#include <cmath>

namespace abalike::app
{

namespace
{
/// The angles charted: every 2.5 degrees over the whole range a slingshot can aim.
constexpr double kFromDeg = -45.0;
constexpr double kToDeg = 90.0;
constexpr double kStepDeg = 2.5;
} // namespace

void RangeChartView::update(const GameSession& session, const std::optional<AimReadout>& aim)
{
    const BirdType* bird = session.currentBird();
    if (!aim || bird == nullptr)
    {
        m_aimDeg.reset();
        return;
    }
    const Key key{session.level().id, bird->name, aim->speedMps};
    if (!(key == m_key) || !m_chart)
    {
        m_key = key;
        m_launch = RangeLaunch{};
        m_launch.model = session.flightModelFor(*bird);
        m_launch.settings.dtS = session.world().dt();
        m_launch.speedMps = aim->speedMps;
        m_launch.heightM = std::max(0.0, session.level().slingshot.y - session.level().groundY);
        m_launch.maxTimeS = 30.0;
        try
        {
            m_chart = rangeChart(m_launch, kFromDeg, kToDeg, kStepDeg);
        }
        catch (const std::exception&)
        {
            m_chart.reset();
        }
        m_aimDeg.reset();
    }
    if (m_aimDeg != aim->angleDeg)
    {
        m_aimDeg = aim->angleDeg;
        m_aimRangeM = rangeAtAngle(m_launch, aim->angleDeg);
    }
}

sf::FloatRect RangeChartView::draw(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topRight,
                                   unsigned titleSize, unsigned rowSize, float scale) const
{
    if (!m_chart || !m_aimDeg)
        return {};
    const RangeChart& chart = *m_chart;
    const float pad = 8.0f * scale;
    const float width = 380.0f * scale;
    const float height = 250.0f * scale;
    const sf::FloatRect rect(topRight.x - width, topRight.y, width, height);
    drawTeachPanel(target, rect, scale, "range chart");
    drawLabel(target, font,
              utf8("Range to the ground by angle, " + formatFixed(m_launch.speedMps, 1) + " m/s (" + m_key.bird + ")"),
              {rect.left + pad, rect.top + pad}, titleSize, palette::kStar);

    // Plot area, with room for the axis labels.
    const float rowHeight = font.getLineSpacing(rowSize);
    const sf::FloatRect area(rect.left + pad + 44.0f * scale, rect.top + pad + font.getLineSpacing(titleSize) * 1.2f,
                             width - 2.0f * pad - 52.0f * scale,
                             height - 2.0f * pad - font.getLineSpacing(titleSize) * 1.2f - 2.4f * rowHeight);
    double lo = 0.0;
    double hi = 1.0;
    for (const auto& r : chart.rangesM)
        if (r)
        {
            lo = std::min(lo, *r);
            hi = std::max(hi, *r);
        }
    hi *= 1.08;
    const auto toPixel = [&](double angle, double range)
    {
        return sf::Vector2f(area.left + area.width * static_cast<float>((angle - kFromDeg) / (kToDeg - kFromDeg)),
                            area.top + area.height * static_cast<float>((hi - range) / (hi - lo)));
    };

    Mesh mesh;
    // Axes and a zero line; grid lines every 45 degrees.
    mesh.addLine(toPixel(kFromDeg, 0.0), toPixel(kToDeg, 0.0), 1.0f * scale, palette::kTextDim);
    for (const double a : {-45.0, 0.0, 45.0, 90.0})
        mesh.addLine(toPixel(a, lo), toPixel(a, hi), 1.0f * scale, faded(palette::kTextDim, 0.35f));
    std::vector<sf::Vector2f> line;
    const auto flush = [&]
    {
        if (line.size() > 1)
            mesh.addPolyline(line, 2.5f * scale, teach::kVelocity);
        line.clear();
    };
    for (std::size_t i = 0; i < chart.anglesDeg.size(); ++i)
    {
        if (!chart.rangesM[i])
        {
            flush(); // a flight still up after 30 s breaks the curve
            continue;
        }
        line.push_back(toPixel(chart.anglesDeg[i], *chart.rangesM[i]));
    }
    flush();
    if (m_aimRangeM)
    {
        const sf::Vector2f aim = toPixel(*m_aimDeg, *m_aimRangeM);
        mesh.addLine({aim.x, area.top}, {aim.x, area.top + area.height}, 1.5f * scale,
                     faded(teach::kAcceleration, 0.7f));
        mesh.addCircle(aim, 6.5f * scale, teach::kAcceleration);
        mesh.addRing(aim, 6.5f * scale, 1.5f * scale, palette::kText);
    }
    if (chart.bestAngleDeg)
    {
        const sf::Vector2f best = toPixel(*chart.bestAngleDeg, *chart.bestRangeM);
        // A ring, drawn over the aim's dot, so both show when the player aims at the best angle.
        mesh.addRing(best, 9.0f * scale, 3.0f * scale, palette::kStar);
    }
    mesh.draw(target);

    // Axis labels.
    for (const double a : {-45.0, 0.0, 45.0, 90.0})
        drawLabel(target, font, utf8(formatFixed(a, 0) + "\u00B0"), {toPixel(a, lo).x, area.top + area.height + 2.0f},
                  rowSize, palette::kTextDim, Align::Centre);
    drawLabel(target, font, utf8(formatFixed(hi / 1.08, 0) + " m"), {area.left - 4.0f * scale, area.top}, rowSize,
              palette::kTextDim, Align::Right);
    drawLabel(target, font, utf8("0 m"), {area.left - 4.0f * scale, toPixel(0.0, 0.0).y - 0.5f * rowHeight}, rowSize,
              palette::kTextDim, Align::Right);

    std::string best = chart.bestAngleDeg ? "best " + formatFixed(*chart.bestAngleDeg, 1) + "\u00B0 \u2192 " +
                                                formatFixed(*chart.bestRangeM, 1) + " m"
                                          : "no angle lands";
    std::string yours = "your " + formatFixed(*m_aimDeg, 1) + "\u00B0 \u2192 " +
                        (m_aimRangeM ? formatFixed(*m_aimRangeM, 1) + " m" : std::string("no landing"));
    const float textTop = rect.top + height - pad - rowHeight;
    drawLabel(target, font, utf8(best), {rect.left + pad, textTop}, rowSize, palette::kStar);
    drawLabel(target, font, utf8(yours), {rect.left + width - pad, textTop}, rowSize, palette::kText, Align::Right);
    return rect;
}

} // namespace abalike::app
