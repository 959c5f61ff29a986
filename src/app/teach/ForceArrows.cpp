#include "teach/ForceArrows.hpp"

#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "render/TextFormat.hpp"
#include "teach/TeachDraw.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace abalike::app
{

namespace
{

/// Gravity's arrow is this long (pixels at scale 1); every force and the acceleration share its scale.
constexpr float kGravityArrowPx = 70.0f;
/// Velocity arrows: pixels per m/s at scale 1.
constexpr float kVelocityPxPerMps = 3.0f;

sf::Vector2f screenDirection(const Vec2& v)
{
    return {static_cast<float>(v.x), -static_cast<float>(v.y)}; // y up in the world, down on the screen
}

double length(const Vec2& v)
{
    return std::hypot(v.x, v.y);
}

/// How well the energy balance closes, in numbers a class reads (no "2.1e-07"): within a thousandth of a joule, or
/// the joules it is off by.
std::string balanceText(double residualJ)
{
    constexpr double kShownJ = 0.001;
    if (std::abs(residualJ) < 0.5 * kShownJ)
        return "balance closes (within 0.001 J)";
    return "balance off by " + formatFixed(std::abs(residualJ), 3) + " J";
}

} // namespace

void drawForceArrows(sf::RenderTarget& target, const sf::Font& font, const Camera& camera, const BirdReadout& bird,
                     bool components, unsigned labelSize, float scale)
{
    const sf::Vector2f centre =
        camera.toScreen({static_cast<float>(bird.state.position.x), static_cast<float>(bird.state.position.y)});
    // Forces in newtons, scaled so that the bird's weight is kGravityArrowPx long (in vacuum at 9.81 if g is 0).
    const double weight = std::max(length(bird.gravityN), bird.massKg * 9.81);
    const float pxPerN = kGravityArrowPx * scale / static_cast<float>(weight);
    const float pxPerMps = kVelocityPxPerMps * scale;
    const float width = 3.0f * scale;
    struct Arrow
    {
        sf::Vector2f tip;
        float width;
        sf::Color colour;
        std::string name;
    };
    const Vec2 v{bird.state.velocity.x, bird.state.velocity.y};
    // The net force, on the forces' scale: the thin arrow is the sum of the thick ones (and m a, which is why the
    // bird's path bends that way; the acceleration itself is a motion, not one more force, and is not drawn here).
    const Vec2 net{bird.gravityN.x + bird.dragN.x, bird.gravityN.y + bird.dragN.y};
    // Velocity first, so that a force pointing along it (a tailwind's push) is drawn over it.
    std::vector<Arrow> arrows{{centre + pxPerMps * screenDirection(v), width, teach::kVelocity, "v"}};
    if (components)
    {
        // vx and vy on the same scale as v: the parallelogram's sides.
        arrows.push_back({centre + pxPerMps * screenDirection({v.x, 0.0}), 1.8f * scale, teach::kVelocity, "vx"});
        arrows.push_back({centre + pxPerMps * screenDirection({0.0, v.y}), 1.8f * scale, teach::kVelocity, "vy"});
    }
    if (bird.windy)
        // Drag acts on this, not on v: it points exactly against it.
        arrows.push_back(
            {centre + pxPerMps * screenDirection(bird.airVelocityMps), 1.8f * scale, teach::kWind, "v \u2212 w"});
    arrows.push_back({centre + pxPerN * screenDirection(bird.gravityN), width, teach::kGravity, "mg"});
    arrows.push_back({centre + pxPerN * screenDirection(bird.dragN), width, teach::kDrag, "drag"});
    arrows.push_back({centre + pxPerN * screenDirection(net), 1.8f * scale, teach::kAcceleration, "net F"});
    Mesh mesh;
    for (const Arrow& arrow : arrows)
        addArrow(mesh, centre, arrow.tip, arrow.width, arrow.colour, 1.0f * scale);
    mesh.draw(target);
    // Each arrow named just beyond its tip, the names kept apart.
    LabelPlacer labels;
    for (const Arrow& arrow : arrows)
    {
        const sf::Vector2f d = arrow.tip - centre;
        const float len = std::hypot(d.x, d.y);
        if (len < 6.0f * scale)
            continue; // too short to name without covering the bird
        labels.draw(target, font, arrow.name, arrow.tip + (8.0f * scale / len) * d, d.x < 0.0f, labelSize,
                    arrow.colour);
    }
}

sf::FloatRect drawForceLegend(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topRight,
                              const BirdReadout& bird, bool hasDrag, bool hasWind, bool components, unsigned titleSize,
                              unsigned rowSize, float scale)
{
    // Forces first, under their own heading, then the motion they cause: velocity and acceleration are not forces.
    std::vector<PanelRow> rows;
    rows.push_back({"t " + withUnit(bird.tS, 2, "s") + "   x " + withUnit(bird.state.position.x, 1, "m") + "   y " +
                        withUnit(bird.state.position.y, 1, "m"),
                    "", sf::Color::Transparent, false});
    rows.push_back({"forces", "", sf::Color::Transparent, true});
    rows.push_back({"  gravity m g", withUnit(length(bird.gravityN), 1, "N"), teach::kGravity});
    if (hasDrag)
        rows.push_back({hasWind ? "  the air's push, against v \u2212 w (drag and wind)" : "  air drag, against v",
                        withUnit(length(bird.dragN), 1, "N"), teach::kDrag});
    else
        rows.push_back({"  no air: gravity is the only force", "", sf::Color::Transparent, false});
    const Vec2 net{bird.gravityN.x + bird.dragN.x, bird.gravityN.y + bird.dragN.y};
    rows.push_back({"  net force \u03A3F", withUnit(length(net), 1, "N"), teach::kAcceleration});
    rows.push_back({"motion", "", sf::Color::Transparent, true});
    rows.push_back({"  velocity v", withUnit(std::hypot(bird.state.velocity.x, bird.state.velocity.y), 1, "m/s"),
                    teach::kVelocity});
    if (components)
        rows.push_back({"    vx, vy",
                        withUnit(bird.state.velocity.x, 1, "m/s") + ", " + withUnit(bird.state.velocity.y, 1, "m/s"),
                        teach::kVelocity});
    if (hasWind && bird.windy)
        rows.push_back({"  velocity in the air v \u2212 w",
                        withUnit(std::hypot(bird.airVelocityMps.x, bird.airVelocityMps.y), 1, "m/s"), teach::kWind});
    rows.push_back({"  acceleration a = \u03A3F / m", withUnit(length(bird.accelerationMps2), 2, "m/s\u00B2"),
                    sf::Color::Transparent});
    const TextPanel panel("Forces on the bird (" + formatFixed(bird.massKg, 1) + " kg)", std::move(rows));
    const sf::Vector2f size = panel.measure(font, titleSize, rowSize, scale);
    if (!fullPanelFits(target, {{topRight.x - size.x, topRight.y}, size}, "forces"))
    {
        std::string summary = "Forces: m g " + withUnit(length(bird.gravityN), 1, "N");
        if (hasDrag)
            summary += ", drag " + withUnit(length(bird.dragN), 1, "N");
        summary += "; v " + withUnit(std::hypot(bird.state.velocity.x, bird.state.velocity.y), 1, "m/s") + ", a " +
                   withUnit(length(bird.accelerationMps2), 2, "m/s\u00B2");
        return drawPanelSummary(target, font, topRight, true, summary, rowSize, scale, "forces");
    }
    return panel.draw(target, font, {topRight.x - size.x, topRight.y}, titleSize, rowSize, scale);
}

sf::FloatRect drawEnergyBars(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topRight,
                             const FlightEnergy& energy, bool atContact, unsigned titleSize, unsigned rowSize,
                             float scale)
{
    struct Bar
    {
        const char* label;
        double joules;
        sf::Color colour;
    };
    const double launch = energy.launchKineticJ + energy.launchPotentialJ;
    const Bar bars[] = {
        {"kinetic \u00BD m v\u00B2", energy.kineticJ, teach::kKinetic},
        {"potential m g y", energy.potentialJ, teach::kPotential},
        {"kinetic + potential", energy.kineticJ + energy.potentialJ, teach::kTotal},
        // A tailwind does work on the bird instead: never "taken by drag -1 J".
        {energy.dragLossJ >= 0.0 ? "taken by drag" : "added by the wind", std::abs(energy.dragLossJ), teach::kLoss},
    };
    const float pad = 8.0f * scale;
    const float rowHeight = font.getLineSpacing(rowSize);
    const float titleHeight = font.getLineSpacing(titleSize) * 1.1f;
    float labelWidth = 0.0f;
    for (const Bar& bar : bars)
        labelWidth = std::max(labelWidth, measureText(font, utf8(bar.label), rowSize).x);
    const float valueWidth = measureText(font, utf8("-00000 J"), rowSize).x;
    const float barWidth = 170.0f * scale;
    // Wide enough for the bars' rows, the title and the balance line under them.
    const std::string title =
        atContact ? "Energy at the first contact" : "Energy: at launch = kinetic + potential + drag";
    const std::string balance =
        "at launch (kinetic + potential) " + formatFixed(launch, 0) + " J   " + balanceText(energy.balanceResidualJ());
    const float width = std::max({2.0f * pad + labelWidth + barWidth + valueWidth + 20.0f * scale,
                                  2.0f * pad + measureText(font, utf8(title), titleSize).x,
                                  2.0f * pad + measureText(font, utf8(balance), rowSize).x});
    const float height = 2.0f * pad + titleHeight + rowHeight * 5.2f;
    const sf::FloatRect rect(topRight.x - width, topRight.y, width, height);
    if (!fullPanelFits(target, rect, "energy"))
        return drawPanelSummary(target, font, topRight, true,
                                std::string(atContact ? "Energy at contact: " : "Energy: ") + "kinetic " +
                                    formatFixed(energy.kineticJ, 0) + " J + potential " +
                                    formatFixed(energy.potentialJ, 0) + " J + drag " +
                                    formatFixed(energy.dragLossJ, 0) + " J = " + formatFixed(launch, 0) + " J",
                                rowSize, scale, "energy");
    drawTeachPanel(target, rect, scale, "energy");
    drawLabel(target, font, utf8(title), {rect.left + pad, rect.top + pad}, titleSize, palette::kStar);

    // Bars share one scale: the launch energy spans barWidth; a negative amount (a tailwind's "loss", a bird
    // below y = 0) reaches left of the zero line.
    const double most = std::max({launch, energy.kineticJ + energy.potentialJ, std::abs(energy.dragLossJ), 1e-9});
    const float zero = rect.left + pad + labelWidth + 10.0f * scale + 0.12f * barWidth;
    const float pxPerJ = 0.88f * barWidth / static_cast<float>(most);
    Mesh mesh;
    float y = rect.top + pad + titleHeight;
    const float barHeight = 0.62f * rowHeight;
    for (const Bar& bar : bars)
    {
        drawLabel(target, font, utf8(bar.label), {rect.left + pad, y}, rowSize, palette::kTextDim);
        const float w = pxPerJ * static_cast<float>(bar.joules);
        const float top = y + 0.5f * (rowHeight - barHeight);
        const float x0 = std::min(zero, zero + w);
        const float x1 = std::max(zero, zero + w);
        mesh.addConvex(std::vector<sf::Vector2f>{{x0, top}, {x1, top}, {x1, top + barHeight}, {x0, top + barHeight}},
                       bar.colour);
        drawLabel(target, font, utf8(formatFixed(bar.joules, 0) + " J"), {rect.left + width - pad, y}, rowSize,
                  palette::kText, Align::Right);
        y += rowHeight;
    }
    // The launch energy as a line across all bars: kinetic + potential + drag always adds up to it.
    const float launchX = zero + pxPerJ * static_cast<float>(launch);
    const float barsTop = rect.top + pad + titleHeight;
    mesh.addLine({launchX, barsTop}, {launchX, y}, 2.0f * scale, palette::kStar);
    mesh.addLine({zero, barsTop}, {zero, y}, 1.0f * scale, palette::kTextDim);
    mesh.draw(target);
    drawLabel(target, font, utf8(balance), {rect.left + pad, y + 0.1f * rowHeight}, rowSize, palette::kStar);
    return rect;
}

} // namespace abalike::app
