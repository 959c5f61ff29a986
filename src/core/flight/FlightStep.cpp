#include <abalike/flight/FlightIntegrator.hpp>

namespace abalike
{

FlightState FlightStep::interpolate(double t) const
{
    const double h = t1 - t0;
    if (h <= 0.0)
        return s1;
    // Cubic Hermite basis on [t0, t1]: exact for the quadratic path of vacuum flight and fourth-order
    // accurate otherwise, which matches RK4's own local error.
    const double u = (t - t0) / h;
    const double u2 = u * u;
    const double u3 = u2 * u;
    const double h00 = 2.0 * u3 - 3.0 * u2 + 1.0;
    const double h10 = u3 - 2.0 * u2 + u;
    const double h01 = -2.0 * u3 + 3.0 * u2;
    const double h11 = u3 - u2;
    // Each number of the state on its own cubic: the value and slope at both ends.
    const auto cubic = [&](double a, double slopeA, double b, double slopeB)
    {
        return h00 * a + h10 * h * slopeA + h01 * b + h11 * h * slopeB;
    };
    return {{cubic(s0.position.x, f0.position.x, s1.position.x, f1.position.x),
             cubic(s0.position.y, f0.position.y, s1.position.y, f1.position.y)},
            {cubic(s0.velocity.x, f0.velocity.x, s1.velocity.x, f1.velocity.x),
             cubic(s0.velocity.y, f0.velocity.y, s1.velocity.y, f1.velocity.y)}};
}

} // namespace abalike
