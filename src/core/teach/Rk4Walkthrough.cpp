#include "flight/FlightStateAlgebra.hpp"

#include <abalike/flight/ClosedForm.hpp>
#include <abalike/flight/FlightRhs.hpp>
#include <abalike/teach/Rk4Walkthrough.hpp>
#include <cmath>
#include <stdexcept>
#include <string>

namespace abalike
{

Rk4Walkthrough walkRk4Step(const FlightModel& model, double t0S, const FlightState& state, double dtS)
{
    if (!(dtS > 0.0) || !std::isfinite(dtS))
        throw std::invalid_argument("the time step must be a finite number > 0");
    if (!std::isfinite(t0S))
        throw std::invalid_argument("the start time must be a finite number");
    if (!isFinite(state))
        throw std::invalid_argument("the state must be finite numbers");
    if (const std::string problem = validateFlightModel(model); !problem.empty())
        throw std::invalid_argument(problem);

    Rk4Walkthrough walk;
    walk.t0S = t0S;
    walk.dtS = dtS;
    walk.state = state;
    visitFlightRhs(model,
                   [&](const auto& rhs)
                   {
                       // odeint evaluates k1 here (we pass it in) and k2..k4 inside do_step: record each call, so
                       // the stages shown are exactly the ones the step used.
                       std::size_t stage = 0;
                       auto recorded = [&](const FlightState& x, FlightState& dxdt, double t)
                       {
                           rhs(x, dxdt, t);
                           if (stage < walk.stages.size())
                               walk.stages[stage++] = {t, x, dxdt};
                       };
                       FlightState k1{};
                       recorded(state, k1, t0S);
                       walk.next = state;
                       FlightRk4().do_step(recorded, walk.next, k1, t0S, dtS);
                   });
    // (k1 + 2 k2 + 2 k3 + k4) / 6, number by number.
    const auto average = [](double k1, double k2, double k3, double k4)
    {
        return (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0;
    };
    const auto& k = walk.stages;
    walk.averageSlope = {
        {average(k[0].slope.position.x, k[1].slope.position.x, k[2].slope.position.x, k[3].slope.position.x),
         average(k[0].slope.position.y, k[1].slope.position.y, k[2].slope.position.y, k[3].slope.position.y)},
        {average(k[0].slope.velocity.x, k[1].slope.velocity.x, k[2].slope.velocity.x, k[3].slope.velocity.x),
         average(k[0].slope.velocity.y, k[1].slope.velocity.y, k[2].slope.velocity.y, k[3].slope.velocity.y)}};
    walk.exact = closedFormState(model, state, dtS);
    return walk;
}

} // namespace abalike
