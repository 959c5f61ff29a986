#pragma once

#include <abalike/flight/FlightModel.hpp>
#include <abalike/flight/Stepper.hpp>
#include <cstddef>
#include <memory>
#include <string_view>

namespace abalike
{

/// Options for integrating a flight.
struct IntegratorSettings
{
    StepperKind stepper = StepperKind::Rk4;
    double dtS = 1.0 / 60.0;    ///< output step (and the step of fixed-step methods)
    double tolerance = 1e-9;    ///< absolute and relative tolerance of dopri5
    bool guardStiffness = true; ///< sub-step fixed-step methods when |lambda| dt leaves their stability region
    double guardLimit = 0.0;    ///< largest |lambda| h of a guarded sub-step; 0 uses defaultGuardLimit(stepper)
    /// Explicit sub-steps an output step may take before the guard hands the rest of it to rosenbrock4 (and the
    /// following steps too while they would need more); 0 uses kDefaultMaxExplicitSubsteps.
    int maxExplicitSubsteps = 0;
};

/// The |lambda| h the stiffness guard allows a fixed-step method per sub-step, chosen by measurement (see
/// docs/flight-numerics.md): small enough that a guarded step is accurate, not merely stable.
double defaultGuardLimit(StepperKind kind);

/// Default of IntegratorSettings::maxExplicitSubsteps, chosen by measurement (see docs/flight-numerics.md).
inline constexpr int kDefaultMaxExplicitSubsteps = 64;

/// What the stiffness guard did during an integration.
enum class GuardAction
{
    Off,      ///< the guard was disabled
    None,     ///< the guard was on and no step needed it
    Substep,  ///< some steps were split into explicit sub-steps
    Implicit, ///< some steps were so stiff that they were handed to the implicit rosenbrock4 stepper
};

/// Name used in JSON: "off", "none", "substep", "rosenbrock4".
std::string_view guardActionName(GuardAction action);

/// One step of an integration: the state and its derivative at both ends, enough for cubic Hermite
/// interpolation (fourth-order accurate, exact for vacuum flight) inside the step.
struct FlightStep
{
    double t0 = 0.0;
    double t1 = 0.0;
    FlightState s0{};
    FlightState s1{};
    FlightState f0{};
    FlightState f1{};

    /// State at time t in [t0, t1] from the cubic Hermite interpolant.
    FlightState interpolate(double t) const;
};

/// Integrates the flight model one output step at a time. The right-hand side is composed once, at
/// construction, from the terms the model has (see FlightRhs); the stepper runs it without indirection.
class FlightIntegrator
{
public:
    /// The model is copied; settings are validated by the caller (see validateFlightModel).
    FlightIntegrator(const FlightModel& model, const IntegratorSettings& settings);
    ~FlightIntegrator();
    FlightIntegrator(FlightIntegrator&&) noexcept;
    FlightIntegrator& operator=(FlightIntegrator&&) noexcept;

    /// Starts a new flight from state s at time t.
    void reset(double t, const FlightState& s);

    /// Advances by one output step of settings().dtS and returns it.
    const FlightStep& step();

    double time() const;
    const FlightState& state() const;
    /// d(state)/dt at the current time and state, from the same composed right-hand side.
    const FlightState& derivative() const;
    /// The composed right-hand side at any (t, s), not counted in rhsEvaluations(): what the world uses to apply
    /// the same forces to a bird once Box2D owns it.
    FlightState rightHandSide(double t, const FlightState& s) const;
    const FlightModel& model() const;
    const IntegratorSettings& settings() const;

    /// Right-hand side evaluations since construction.
    std::size_t rhsEvaluations() const;
    /// Internal steps taken beyond one per output step (stiffness guard sub-steps, adaptive steps).
    std::size_t substeps() const;
    /// Largest |lambda| * h seen by a fixed-step method, h being the step it actually took.
    double maxStiffnessRatio() const;
    /// What the stiffness guard did since construction.
    GuardAction guardAction() const;

    class Impl;

private:
    std::unique_ptr<Impl> m_impl;
};

} // namespace abalike
