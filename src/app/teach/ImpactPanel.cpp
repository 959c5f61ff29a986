#include "teach/ImpactPanel.hpp"

#include <algorithm>

#include "render/TextFormat.hpp"
#include "teach/TeachDraw.hpp"

#include <cmath>

namespace abalike::app
{

namespace
{

double speed(const BodyVelocity& v)
{
    return std::hypot(v.vx, v.vy);
}

std::string momentum(double massKg, const BodyVelocity& v)
{
    return withUnit(massKg * speed(v), 1, "kg\u00B7m/s");
}

/// Kinetic energy, translation and rotation; the rotation's share is named when there is any, so that the total
/// never holds energy the panel does not show.
std::string kinetic(double massKg, double inertia, const BodyVelocity& v)
{
    const double spin = 0.5 * inertia * v.omegaRadPerS * v.omegaRadPerS;
    std::string text = withUnit(0.5 * massKg * speed(v) * speed(v) + spin, 1, "J");
    if (spin >= 0.05)
        text += " (spin " + withUnit(spin, 1, "J") + ")";
    return text;
}

} // namespace

sf::FloatRect drawImpactPanel(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topRight,
                              const FirstImpact& impact, double bodyStrengthNs, unsigned titleSize, unsigned rowSize,
                              float scale)
{
    const std::string body = impact.bodyType + (impact.bodyKind == EntityKind::Pig ? " pig" : " block");
    const auto pBefore = impact.momentumBefore();
    const auto pAfter = impact.momentumAfter();
    std::vector<PanelRow> rows{
        {"bird, " + formatFixed(impact.birdMassKg, 1) + " kg", "", sf::Color::Transparent, true},
        {"  before: " + withUnit(speed(impact.birdBefore), 1, "m/s"),
         momentum(impact.birdMassKg, impact.birdBefore) + "   " +
             kinetic(impact.birdMassKg, impact.birdInertiaKgM2, impact.birdBefore)},
        {"  after: " + withUnit(speed(impact.birdAfter), 1, "m/s") + ", " +
             withUnit(impact.birdAfter.omegaRadPerS, 1, "rad/s"),
         momentum(impact.birdMassKg, impact.birdAfter) + "   " +
             kinetic(impact.birdMassKg, impact.birdInertiaKgM2, impact.birdAfter)},
        {body + ", " + formatFixed(impact.bodyMassKg, 1) + " kg", "", sf::Color::Transparent, true},
        {"  before: " + withUnit(speed(impact.bodyBefore), 1, "m/s"),
         momentum(impact.bodyMassKg, impact.bodyBefore) + "   " +
             kinetic(impact.bodyMassKg, impact.bodyInertiaKgM2, impact.bodyBefore)},
        {"  after: " + withUnit(speed(impact.bodyAfter), 2, "m/s") + ", " +
             withUnit(impact.bodyAfter.omegaRadPerS, 2, "rad/s"),
         momentum(impact.bodyMassKg, impact.bodyAfter) + "   " +
             kinetic(impact.bodyMassKg, impact.bodyInertiaKgM2, impact.bodyAfter)},
        {"together", "", sf::Color::Transparent, true},
        {"  momentum before \u2192 after", withUnit(std::hypot(pBefore[0], pBefore[1]), 1, "") + "\u2192 " +
                                               withUnit(std::hypot(pAfter[0], pAfter[1]), 1, "kg\u00B7m/s")},
        {"  kinetic energy (with spin) before \u2192 after",
         withUnit(impact.kineticBeforeJ(), 0, "") + "\u2192 " + withUnit(impact.kineticAfterJ(), 0, "J")},
    };
    std::string damage = withUnit(impact.damageNs, 1, "N\u00B7s");
    if (bodyStrengthNs > 0.0)
        damage +=
            " of " + withUnit(bodyStrengthNs, 0, "N\u00B7s") + (impact.damageNs >= bodyStrengthNs ? ": broke it" : "");
    if (const auto e = impact.restitution())
        rows.push_back({"  restitution e = separating / closing speed", formatFixed(*e, 2)});
    // Strength is an impulse the body can take, not energy: its own heading keeps it apart from the joules above.
    rows.push_back({"strength (an impulse in N\u00B7s, not energy)", "", sf::Color::Transparent, true});
    rows.push_back({"  impulse taken as damage", damage});
    // Momentum is conserved only if nothing else pushed during the step: a block standing on others is held.
    const double change = std::hypot(pAfter[0] - pBefore[0], pAfter[1] - pBefore[1]);
    if (change > 0.05 * std::hypot(pBefore[0], pBefore[1]))
        rows.push_back({"Momentum changed: what the body stands on pushed back too.", ""});
    else
        rows.push_back({"Momentum is kept; the kinetic energy lost became heat, sound and deformation.", ""});
    const TextPanel panel("First impact: t = " + withUnit(impact.tS, 3, "s"), std::move(rows));
    const sf::Vector2f size = panel.measure(font, titleSize, rowSize, scale);
    const sf::Vector2f at(std::max(0.0f, topRight.x - size.x), topRight.y);
    if (!fullPanelFits(target, {at, size}, "first impact"))
        return drawPanelSummary(target, font, topRight, true,
                                "First impact: bird " + withUnit(speed(impact.birdBefore), 1, "") + "\u2192 " +
                                    withUnit(speed(impact.birdAfter), 1, "m/s") + ", " + damage + " taken",
                                rowSize, scale, "first impact");
    return panel.draw(target, font, at, titleSize, rowSize, scale);
}

} // namespace abalike::app
