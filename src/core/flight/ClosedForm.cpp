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
        s.position.x += s0.velocity.x * t;
        s.position.y += s0.velocity.y * t - 0.5 * g * t * t;
        s.velocity.y -= g * t;
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
    s.position.x += ux * t + (s0.velocity.x - ux) * oneMinusE / k;
    s.position.y += uy * t + (s0.velocity.y - uy) * oneMinusE / k;
    s.velocity.x = ux + (s0.velocity.x - ux) * e;
    s.velocity.y = uy + (s0.velocity.y - uy) * e;
    return s;
}

} // namespace abalike
