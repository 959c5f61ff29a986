#include <abalike/flight/ClosedForm.hpp>
#include <cmath>

namespace abalike
{

bool hasClosedForm(const FlightModel& model)
{
    return (activeTerms(model) & (kQuadraticDragTerm | kGustTerm)) == 0;
}

std::optional<FlightState> closedFormState(const FlightModel& model, const FlightState& s0, double t)
{
    const unsigned terms = activeTerms(model);
    if ((terms & (kQuadraticDragTerm | kGustTerm)) != 0)
        return std::nullopt;
    const double g = (terms & kGravityTerm) != 0 ? model.gravity : 0.0;
    FlightState s = s0;
    if ((terms & kLinearDragTerm) == 0)
    {
        s[0] += s0[2] * t;
        s[1] += s0[3] * t - 0.5 * g * t * t;
        s[3] -= g * t;
        return s;
    }
    // Linear drag relaxes v towards the terminal velocity u = w - (g/k) y-hat with rate k = b/m;
    // expm1 keeps 1 - exp(-kt) accurate when kt is small.
    const double k = model.linearDrag / model.massKg;
    const double wx = (terms & kWindTerm) != 0 ? model.windX : 0.0;
    const double wy = (terms & kWindTerm) != 0 ? model.windY : 0.0;
    const double ux = wx;
    const double uy = wy - g / k;
    const double oneMinusE = -std::expm1(-k * t);
    const double e = 1.0 - oneMinusE;
    s[0] += ux * t + (s0[2] - ux) * oneMinusE / k;
    s[1] += uy * t + (s0[3] - uy) * oneMinusE / k;
    s[2] = ux + (s0[2] - ux) * e;
    s[3] = uy + (s0[3] - uy) * e;
    return s;
}

} // namespace abalike
