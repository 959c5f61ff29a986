#include <abalike/flight/ClosedForm.hpp>
#include <abalike/flight/FlightRhs.hpp>
#include <abalike/teach/Rk4Walkthrough.hpp>
#include <boost/numeric/odeint.hpp>
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
    for (const double v : state)
        if (!std::isfinite(v))
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
                       boost::numeric::odeint::runge_kutta4<FlightState>().do_step(recorded, walk.next, k1, t0S, dtS);
                   });
    for (std::size_t i = 0; i < walk.averageSlope.size(); ++i)
        walk.averageSlope[i] = (walk.stages[0].slope[i] + 2.0 * walk.stages[1].slope[i] +
                                2.0 * walk.stages[2].slope[i] + walk.stages[3].slope[i]) /
                               6.0;
    walk.exact = closedFormState(model, state, dtS);
    return walk;
}

} // namespace abalike
