#include "teach/ImpactPanel.hpp"

#include <algorithm>

#include "render/TextFormat.hpp"
#include "teach/TeachDraw.hpp"
#include <abalike/teach/ImpactAccount.hpp>

#include <cmath>
#include <numbers>

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

/// A momentum or impulse as its components, "(+31.7, −51.1)": the balance only closes with directions.
std::string components(const Vec2& v)
{
    const auto part = [](double x)
    {
        const std::string digits = formatFixed(std::abs(x), 1);
        std::string text = digits == "0.0" ? " " : x < 0.0 ? "\u2212" : "+";
        text += digits;
        return text;
    };
    std::string text = "(";
    text += part(v.x);
    text += ", ";
    text += part(v.y);
    text += ")";
    return text;
}

bool shows(const Vec2& v)
{
    return std::hypot(v.x, v.y) >= 0.05;
}

/// The momentum balance of the impact's step: each change and every push from outside the pair, in components, and
/// what is left when they are subtracted (zero but for rounding), so a class can check conservation on any shot.
void addBalanceRows(std::vector<PanelRow>& rows, const FirstImpact& impact, const std::string& body)
{
    const ImpactBalance& b = impact.balance;
    rows.push_back({"momentum in that step, (x, y) kg\u00B7m/s", "", sf::Color::Transparent, true});
    // One impulse between the two, equal and opposite (Newton's third law): what the bird gave the body, which gave
    // the bird the same back. The solver's push and the break rule's refund are bookkeeping and stay out.
    rows.push_back({"  bird and " + body + " pushed each other: on the " + body, components(impact.exchanged())});
    rows.push_back({"  change of the bird", components(impact.birdChange())});
    rows.push_back({"  change of the " + body, components(impact.bodyChange())});
    // Only the pushes from outside the pair that acted: each one is why the two changes do not cancel.
    if (shows(b.supports))
        rows.push_back({"  + push of what the " + body + " stands on or touches", components(b.supports)});
    if (shows(b.gravity))
        rows.push_back({"  + weight over the step", components(b.gravity)});
    if (shows(b.breakThrough))
        rows.push_back({"  + momentum the breaking " + body + " handed on to the bird", components(b.breakThrough)});
    if (shows(b.birdOtherContacts))
        rows.push_back({"  + what else the bird touched", components(b.birdOtherContacts)});
    const auto residual = impact.balanceResidual();
    rows.push_back({"  changes \u2212 pushes from outside", components(residual)});
}

} // namespace

sf::FloatRect drawImpactPanel(sf::RenderTarget& target, const sf::Font& font, sf::Vector2f topRight,
                              const FirstImpact& impact, bool university, unsigned titleSize, unsigned rowSize,
                              float scale)
{
    const std::string body = impact.bodyType + (impact.bodyKind == EntityKind::Pig ? " pig" : " block");
    // One row per body, before \u2192 after the step: speed and spin, momentum, kinetic energy.
    const auto spin = [university](double omegaRadPerS)
    {
        return university ? withUnit(omegaRadPerS, 1, "rad/s")
                          : withUnit(omegaRadPerS / (2.0 * std::numbers::pi), 2, "turns/s");
    };
    const auto bodyRow = [&spin](const std::string& name, double massKg, double inertia, const BodyVelocity& before,
                                 const BodyVelocity& after) -> PanelRow
    {
        const double kineticBefore =
            0.5 * massKg * speed(before) * speed(before) + 0.5 * inertia * before.omegaRadPerS * before.omegaRadPerS;
        return {name + ", " + formatFixed(massKg, 1) + " kg: " + formatFixed(speed(before), 1) + " \u2192 " +
                    withUnit(speed(after), 2, "m/s") + ", " + spin(after.omegaRadPerS),
                formatFixed(massKg * speed(before), 1) + " \u2192 " + momentum(massKg, after) + "   " +
                    formatFixed(kineticBefore, 1) + " \u2192 " + kinetic(massKg, inertia, after)};
    };
    std::vector<PanelRow> rows{
        bodyRow("bird", impact.birdMassKg, impact.birdInertiaKgM2, impact.birdBefore, impact.birdAfter),
        bodyRow(body, impact.bodyMassKg, impact.bodyInertiaKgM2, impact.bodyBefore, impact.bodyAfter),
        {"together: kinetic energy (with spin)",
         withUnit(impact.kineticBeforeJ(), 0, "") + "\u2192 " + withUnit(impact.kineticAfterJ(), 0, "J")},
    };
    // Bounciness is measured only where something can rebound: a body that broke gave way instead.
    const char* bounceName =
        university ? "restitution e = separating / closing speed" : "bounciness e = separating / closing speed";
    if (impact.broke)
        rows.push_back({bounceName, "it broke: no rebound to measure"});
    else if (const auto e = impact.restitution())
        rows.push_back({bounceName, formatFixed(*e, 2)});
    addBalanceRows(rows, impact, impact.bodyKind == EntityKind::Pig ? "pig" : "block");
    std::string damage = withUnit(impact.damageNs, 1, "N\u00B7s");
    if (impact.strengthBeforeNs > 0.0)
        damage = damageOfStrength(impact.broke ? impact.strengthBeforeNs : impact.damageNs, impact.strengthBeforeNs) +
                 (impact.broke ? ": all of it, it broke" : "");
    // Strength is an impulse the body can take, not energy: its own heading keeps it apart from the joules above.
    rows.push_back({"strength: impulse taken as damage (N\u00B7s, not energy)", damage});
    // With no push from outside the pair, momentum is kept: say where the lost energy went.
    if (!shows(impact.balance.supports) && !shows(impact.balance.gravity) && !shows(impact.balance.breakThrough))
        rows.push_back({"Momentum is kept; the kinetic energy lost became heat, sound and deformation.", ""});
    const TextPanel panel("First impact: t = " + withUnit(impact.tS, 3, "s") + ", before \u2192 after its step",
                          std::move(rows));
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
