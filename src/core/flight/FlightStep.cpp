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
    FlightState s{};
    for (std::size_t i = 0; i < s.size(); ++i)
        s[i] = h00 * s0[i] + h10 * h * f0[i] + h01 * s1[i] + h11 * h * f1[i];
    return s;
}

} // namespace abalike
