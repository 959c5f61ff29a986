#pragma once

#include <abalike/flight/FlightModel.hpp>
#include <array>
#include <optional>

namespace abalike
{

/// One stage of an RK4 step: where the right-hand side was evaluated and the slope it gave there.
struct Rk4Stage
{
    double tS = 0.0;
    FlightState at{};    ///< the state the slope was evaluated at
    FlightState slope{}; ///< f(t, at) = d(x, y, vx, vy)/dt: a derivative, not an increment h f
};

/// One plain RK4 step laid open for teaching: the four slopes, their weighted average and the result.
struct Rk4Walkthrough
{
    double t0S = 0.0;
    double dtS = 0.0;
    FlightState state{};              ///< the state the step starts from
    std::array<Rk4Stage, 4> stages{}; ///< k1..k4
    FlightState averageSlope{};       ///< (k1 + 2 k2 + 2 k3 + k4) / 6: the slope the step actually takes
    FlightState next{};               ///< state + dt * averageSlope, as odeint's runge_kutta4 computes it
    std::optional<FlightState> exact; ///< the closed form after dt, where one exists (vacuum, linear drag)
};

/// One RK4 step of the model from `state` at time t0 (no stiffness guard, no sub-steps), by the same odeint
/// runge_kutta4 the preview and the world use, so `next` has the same bits as their step. Throws
/// std::invalid_argument for an invalid model or a step that is not a finite number > 0.
Rk4Walkthrough walkRk4Step(const FlightModel& model, double t0S, const FlightState& state, double dtS);

} // namespace abalike
