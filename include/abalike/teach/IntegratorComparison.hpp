#pragma once

#include <abalike/flight/Prediction.hpp>
#include <optional>
#include <string>

namespace abalike
{

/// A method the teaching overlay compares with the real RK4 preview: explicit Euler, semi-implicit Euler (Box2D's
/// scheme) or RK4 at a fixed step, or dopri5 at a tolerance.
struct ComparisonMethod
{
    StepperKind stepper = StepperKind::Euler;
    double dtS = 1.0 / 60.0; ///< fixed-step methods: 1/240 to 1/15 s
    double tolerance = 1e-6; ///< dopri5: 1e-12 to 1e-2

    /// Integrator settings for this method: plain (no stiffness guard), so it shows the method as it is; dopri5
    /// reports at the physics step.
    IntegratorSettings settings(double physicsDtS) const;
    /// e.g. "explicit Euler, dt = 1/60 s", "dopri5, tol = 1e-6".
    std::string label() const;
};

/// Shortest and longest step of a compared fixed-step method, and the tolerance range of dopri5.
inline constexpr double kComparisonMinDtS = 1.0 / 240.0;
inline constexpr double kComparisonMaxDtS = 1.0 / 15.0;
inline constexpr double kComparisonMinTolerance = 1e-12;
inline constexpr double kComparisonMaxTolerance = 1e-2;

/// What another method would have predicted, measured against the real path.
struct IntegratorComparison
{
    ComparisonMethod method;
    PredictedFlight flight;              ///< its path, ended by the same limits (contact, landing, time)
    double maxErrorM = 0.0;              ///< largest distance from the real path at its own output times (m)
    std::optional<double> contactErrorM; ///< distance between its first contact and the real one, if both touch
    /// What each method costs, when asked for (ComparisonCost::Measure): the median microseconds of integrating the
    /// real flight's time with it and with the real RK4, without contact tests (the method alone).
    std::optional<double> costUs;
    std::optional<double> realCostUs;
};

/// Whether compareIntegrator also times the two methods (a few milliseconds: the teaching overlay shows it; tests
/// that check paths need not wait for it).
enum class ComparisonCost
{
    Skip,
    Measure,
};

/// Flies the launch s0 with `method` under the same limits as the real flight and measures it against `real` (the
/// RK4 preview of the same launch, interpolated between its points with the model's derivatives). Throws
/// std::invalid_argument for a step or tolerance outside the ranges above or an invalid model.
IntegratorComparison compareIntegrator(const FlightModel& model, const FlightState& s0, const ComparisonMethod& method,
                                       double physicsDtS, const PredictedFlight& real, const PredictionLimits& limits,
                                       ComparisonCost cost = ComparisonCost::Skip);

/// Position on a predicted path at time t, on the cubic Hermite interpolant through its points (their derivatives
/// from the model's right-hand side); the ends of the path outside [first, last].
FlightState pathStateAt(const FlightIntegrator& rhs, const PredictedFlight& flight, double tS);

} // namespace abalike
