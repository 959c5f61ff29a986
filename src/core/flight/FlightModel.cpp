#include <abalike/flight/FlightModel.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace abalike
{

Vec2 GustDef::windAt(double t) const
{
    if (kind == Kind::Sine)
    {
        // Written as FlightRhs evaluates it (omega t + phase), so both give the same bits.
        const double omega = 2.0 * std::numbers::pi / periodS;
        const double s = std::sin(omega * t + phaseRad);
        return {amplitudeX * s, amplitudeY * s};
    }
    // Last step that has started; before the first one there is no gust.
    const auto after = std::upper_bound(steps.begin(), steps.end(), t,
                                        [](double time, const Step& step) { return time < step.startS; });
    if (after == steps.begin())
        return {0.0, 0.0};
    const Step& current = *(after - 1);
    return {current.windX, current.windY};
}

Vec2 GustDef::rateAt(double t) const
{
    if (kind != Kind::Sine)
        return {0.0, 0.0};
    const double omega = 2.0 * std::numbers::pi / periodS;
    const double c = omega * std::cos(omega * t + phaseRad);
    return {amplitudeX * c, amplitudeY * c};
}

unsigned activeTerms(const FlightModel& model)
{
    unsigned terms = 0;
    if (model.gravity != 0.0)
        terms |= kGravityTerm;
    if (model.linearDrag != 0.0)
        terms |= kLinearDragTerm;
    if (model.quadraticDrag != 0.0)
        terms |= kQuadraticDragTerm;
    const bool hasDrag = (terms & (kLinearDragTerm | kQuadraticDragTerm)) != 0;
    if (hasDrag && (model.windX != 0.0 || model.windY != 0.0))
        terms |= kWindTerm;
    if (hasDrag && model.gusts)
        terms |= kGustTerm;
    return terms;
}

std::vector<std::string> termNames(unsigned terms)
{
    static const char* const kNames[] = {"gravity", "linear_drag", "quadratic_drag", "wind", "gusts"};
    std::vector<std::string> names;
    for (unsigned bit = 0; bit < 5; ++bit)
        if ((terms & (1u << bit)) != 0)
            names.emplace_back(kNames[bit]);
    return names;
}

std::string validateFlightModel(const FlightModel& model)
{
    std::ostringstream problem;
    auto check = [&](const char* name, double value, bool ok, const char* expected)
    {
        if (!problem.str().empty())
            return;
        if (!std::isfinite(value))
            problem << name << " must be a finite number, got " << value;
        else if (!ok)
            problem << name << " must be " << expected << ", got " << value;
    };
    check("gravity", model.gravity, model.gravity >= 0.0, ">= 0 (it is the magnitude along -y)");
    check("mass", model.massKg, model.massKg > 0.0, "> 0 kg");
    check("linear drag", model.linearDrag, model.linearDrag >= 0.0, ">= 0 kg/s");
    check("quadratic drag", model.quadraticDrag, model.quadraticDrag >= 0.0, ">= 0 kg/m");
    check("wind x", model.windX, true, "");
    check("wind y", model.windY, true, "");
    if (model.gusts && problem.str().empty())
    {
        const GustDef& g = *model.gusts;
        if (g.kind == GustDef::Kind::Sine)
        {
            check("gust amplitude x", g.amplitudeX, true, "");
            check("gust amplitude y", g.amplitudeY, true, "");
            check("gust period", g.periodS, g.periodS > 0.0, "> 0 s");
            check("gust phase", g.phaseRad, true, "");
        }
        else
        {
            for (std::size_t i = 0; i < g.steps.size(); ++i)
            {
                check("gust step start", g.steps[i].startS, i == 0 || g.steps[i].startS > g.steps[i - 1].startS,
                      "increasing");
                check("gust wind x", g.steps[i].windX, true, "");
                check("gust wind y", g.steps[i].windY, true, "");
            }
        }
    }
    return problem.str();
}

double quadraticDragCoefficient(double airDensityKgPerM3, double dragCoefficient, double radiusM)
{
    const double area = std::numbers::pi * radiusM * radiusM;
    return 0.5 * airDensityKgPerM3 * dragCoefficient * area;
}

FlightState launchState(double x0, double y0, double speedMps, double angleDeg)
{
    const double angle = angleDeg * std::numbers::pi / 180.0;
    return {{x0, y0}, {speedMps * std::cos(angle), speedMps * std::sin(angle)}};
}

} // namespace abalike
