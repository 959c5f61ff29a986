#pragma once

#include <optional>
#include <string_view>

namespace abalike
{

/// The integration schemes the flight model can be solved with.
enum class StepperKind
{
    Euler,             ///< explicit Euler, first order
    SemiImplicitEuler, ///< v += dt a, then x += dt v: the scheme Box2D uses
    Rk4,               ///< classic fourth-order Runge-Kutta (odeint runge_kutta4), the preview default
    Dopri5,            ///< adaptive Dormand-Prince 5(4) with dense output (odeint runge_kutta_dopri5)
    Analytic,          ///< closed form, where one exists (vacuum; linear drag with constant wind)
};

/// Name used on the command line and in JSON ("euler", "semi-implicit-euler", "rk4", "dopri5", "analytic").
std::string_view stepperName(StepperKind kind);

/// Parses a stepper name; nullopt if it is not one of the names above.
std::optional<StepperKind> parseStepper(std::string_view name);

} // namespace abalike
