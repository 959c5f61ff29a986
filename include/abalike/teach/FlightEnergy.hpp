#pragma once

#include <abalike/flight/FlightIntegrator.hpp>
#include <vector>

namespace abalike
{

/// The energy balance of a free flight at one moment: launch energy = kinetic + potential + drag loss.
struct FlightEnergy
{
    double tS = 0.0;         ///< time since launch
    FlightState state{};     ///< the flight's state then (interpolated inside its step)
    double kineticJ = 0.0;   ///< m |v|^2 / 2
    double potentialJ = 0.0; ///< m g y, y in the same coordinates as the launch (a level's y = 0)
    double dragLossJ = 0.0;  ///< work done against drag since launch; negative when a tailwind added energy
    double launchKineticJ = 0.0;
    double launchPotentialJ = 0.0;

    /// Launch energy minus kinetic, potential and drag loss: zero up to the integrator's accuracy.
    double balanceResidualJ() const { return launchKineticJ + launchPotentialJ - (kineticJ + potentialJ + dragLossJ); }
};

/// Flies a launch with its own FlightIntegrator -- the same model and settings give the same steps as the preview
/// and the world -- and integrates the drag loss along it: the power of drag (and wind) on the bird,
/// m (a + g y-hat) . v, on each step's cubic Hermite interpolant with 3-point Gauss-Legendre quadrature (split
/// where a stepwise gust jumps), so the loss is as accurate as the path (fourth order).
class FlightEnergyTracker
{
public:
    /// Throws std::invalid_argument for an invalid model or settings (as FlightIntegrator does).
    FlightEnergyTracker(const FlightModel& model, const IntegratorSettings& settings, const FlightState& s0);

    /// The balance at time t >= 0 since launch. Steps forward as far as needed; an earlier time than the last
    /// query's step starts over from the launch.
    FlightEnergy at(double tS);

private:
    /// Takes the next step and splits it into its smooth pieces.
    void advance();
    /// Integral of the drag power over [t0, t1] inside the last step.
    double dragWork(double t0, double t1) const;
    /// The state at time t inside the last step.
    FlightState stateAt(double t) const;

    FlightIntegrator m_integrator;
    FlightState m_s0{};
    /// The last step, as one piece, or as several where a stepwise gust jumps inside it (the integrator ends a
    /// sub-step exactly there; one cubic across the kink in the velocity would lose the fourth order).
    std::vector<FlightStep> m_pieces;
    double m_lossBeforeStepJ = 0.0; ///< drag loss from launch to the start of the last step
};

/// The balance at time t since launch of the flight from s0, flown as FlightEnergyTracker flies it.
FlightEnergy flightEnergyAt(const FlightModel& model, const IntegratorSettings& settings, const FlightState& s0,
                            double tS);

} // namespace abalike
