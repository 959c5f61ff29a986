#pragma once

#include <abalike/flight/FlightState.hpp>
#include <optional>
#include <string>
#include <vector>

namespace abalike
{

/// Time-varying wind added to the constant wind: piecewise-constant steps or a smooth sine.
struct GustDef
{
    enum class Kind
    {
        Steps,
        Sine
    };
    struct Step
    {
        double startS = 0.0; ///< the step holds from this time until the next step starts
        double windX = 0.0;
        double windY = 0.0;

        bool operator==(const Step&) const = default;
    };
    Kind kind = Kind::Steps;
    std::vector<Step> steps; ///< Kind::Steps, sorted by startS
    double amplitudeX = 0.0; ///< Kind::Sine: w(t) += A sin(2 pi t / T + phase)
    double amplitudeY = 0.0;
    double periodS = 1.0;
    double phaseRad = 0.0;

    bool operator==(const GustDef&) const = default;

    /// Gust wind at time t (m/s), without the constant wind.
    Vec2 windAt(double t) const;
    /// d(windAt)/dt (m/s^2); zero between the jumps of Kind::Steps.
    Vec2 rateAt(double t) const;
};

/// The forces on a bird in free flight. Every term is optional; a term that is absent (zero) is not
/// evaluated at all by the right-hand side built from this model (see FlightRhs).
struct FlightModel
{
    double gravity = 9.81;      ///< magnitude of g, acting along -y (m/s^2)
    double massKg = 1.0;        ///< bird mass (kg)
    double linearDrag = 0.0;    ///< b in F = -b (v - w)  (kg/s)
    double quadraticDrag = 0.0; ///< c in F = -c |v - w| (v - w)  (kg/m)
    double windX = 0.0;         ///< constant wind w (m/s); acts only through drag
    double windY = 0.0;
    std::optional<GustDef> gusts;
};

/// Bits naming the force terms a model actually has.
enum FlightTerm : unsigned
{
    kGravityTerm = 1u << 0,
    kLinearDragTerm = 1u << 1,
    kQuadraticDragTerm = 1u << 2,
    kWindTerm = 1u << 3,
    kGustTerm = 1u << 4,
};
inline constexpr unsigned kAllFlightTerms = 31u;

/// The terms that contribute to the model's acceleration. Wind and gusts act through drag, so they
/// are active only when the model has drag.
unsigned activeTerms(const FlightModel& model);

/// Names of the terms in the bit set, in a fixed order: gravity, linear_drag, quadratic_drag, wind, gusts.
std::vector<std::string> termNames(unsigned terms);

/// An empty string when the model is physically meaningful, otherwise what is wrong with it.
std::string validateFlightModel(const FlightModel& model);

/// Quadratic drag coefficient c = 1/2 rho Cd A for a bird of circular cross-section.
double quadraticDragCoefficient(double airDensityKgPerM3, double dragCoefficient, double radiusM);

/// Initial state of a launch: position, speed and angle in degrees above +x.
FlightState launchState(double x0, double y0, double speedMps, double angleDeg);

} // namespace abalike
