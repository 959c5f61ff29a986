#pragma once

#include <abalike/flight/FlightModel.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace abalike::detail
{

/// odeint's rosenbrock4 (its default fourth-order coefficients with a third-order embedded error) and its
/// rosenbrock4_controller, written for the flight state. odeint's own needs uBLAS, whose storage calls
/// std::allocator::construct and so does not compile as C++20 with Boost 1.74.
///
/// The Jacobian of the flight ODE is [[0, I], [0, A]] with A = d(acceleration)/d(velocity), so the stage
/// equations (I / (gamma h) - J) g = b reduce to one 2 x 2 solve.
class Rosenbrock4
{
public:
    /// Integrates x from t0 to t1 at absolute and relative tolerance tol. deriv(s, dsdt, t) is the right-hand
    /// side; jacobian(s, t, dadv, dadt) gives A (row-major) and the acceleration's explicit time derivative.
    /// Returns the number of accepted steps.
    template <class Deriv, class Jacobian>
    std::size_t integrate(Deriv&& deriv, Jacobian&& jacobian, FlightState& x, double t0, double t1, double tol)
    {
        double t = t0;
        double dt = m_dtHint > 0.0 ? std::min(m_dtHint, t1 - t0) : t1 - t0;
        std::size_t accepted = 0;
        // Bounded even if the state turns non-finite: every rejection shrinks dt, every acceptance advances t.
        for (int attempt = 0; attempt < kMaxAttempts && t < t1; ++attempt)
        {
            const bool last = dt >= t1 - t;
            const double h = last ? t1 - t : dt;
            FlightState xNew{};
            FlightState xErr{};
            step(deriv, jacobian, x, t, h, xNew, xErr);
            const double err = errorNorm(x, xNew, xErr, tol);
            double fac = std::max(kFacMin, std::min(kFacMax, std::pow(err, 0.25) / kSafety));
            if (err <= 1.0)
            {
                if (m_errOld > 0.0)
                {
                    // Gustafsson's predictive control, as in odeint's controller.
                    const double pred = std::max(
                        kFacMin, std::min(kFacMax, (m_dtOld / h) * std::pow(err * err / m_errOld, 0.25) / kSafety));
                    fac = std::max(fac, pred);
                }
                m_dtOld = h;
                m_errOld = std::max(0.01, err);
                x = xNew;
                t = last ? t1 : t + h;
                ++accepted;
                const double next = h / fac;
                dt = m_lastRejected ? std::min(next, h) : next;
                m_lastRejected = false;
                if (!last)
                    m_dtHint = dt;
            }
            else
            {
                dt = h / fac;
                m_lastRejected = true;
            }
        }
        return accepted;
    }

    /// Forgets the step size and error history (a new flight).
    void reset()
    {
        m_dtHint = 0.0;
        m_dtOld = 0.0;
        m_errOld = 0.0;
        m_lastRejected = false;
    }

private:
    /// The stages work on the state's four numbers in odeint's order (FlightState's iterator).
    using Numbers = std::array<double, 4>;

    static constexpr int kMaxAttempts = 100000;
    static constexpr double kSafety = 0.9;
    static constexpr double kFacMax = 5.0;
    static constexpr double kFacMin = 1.0 / 6.0;

    // The parameter set of odeint's default_rosenbrock_coefficients.
    static constexpr double kGamma = 0.25;
    static constexpr double kD1 = 0.25, kD2 = -0.1043, kD3 = 0.1035, kD4 = 0.3620000000000023e-01;
    static constexpr double kC2 = 0.386, kC3 = 0.21, kC4 = 0.63;
    static constexpr double kC21 = -0.5668800000000000e+01, kA21 = 0.1544000000000000e+01;
    static constexpr double kC31 = -0.2430093356833875e+01, kC32 = -0.2063599157091915e+00;
    static constexpr double kA31 = 0.9466785280815826e+00, kA32 = 0.2557011698983284e+00;
    static constexpr double kC41 = -0.1073529058151375e+00, kC42 = -0.9594562251023355e+01,
                            kC43 = -0.2047028614809616e+02;
    static constexpr double kA41 = 0.3314825187068521e+01, kA42 = 0.2896124015972201e+01, kA43 = 0.9986419139977817e+00;
    static constexpr double kC51 = 0.7496443313967647e+01, kC52 = -0.1024680431464352e+02,
                            kC53 = -0.3399990352819905e+02, kC54 = 0.1170890893206160e+02;
    static constexpr double kA51 = 0.1221224509226641e+01, kA52 = 0.6019134481288629e+01, kA53 = 0.1253708332932087e+02,
                            kA54 = -0.6878860361058950e+00;
    static constexpr double kC61 = 0.8083246795921522e+01, kC62 = -0.7981132988064893e+01,
                            kC63 = -0.3152159432874371e+02, kC64 = 0.1631930543123136e+02,
                            kC65 = -0.6058818238834054e+01;

    /// Solves (c I - J) g = b in place, J = [[0, I], [0, A]].
    struct StageSolver
    {
        double c = 0.0;
        double m00 = 0.0, m01 = 0.0, m10 = 0.0, m11 = 0.0, det = 1.0;

        StageSolver(double cIn, const std::array<double, 4>& a)
            : c(cIn), m00(cIn - a[0]), m01(-a[1]), m10(-a[2]), m11(cIn - a[3]), det(m00 * m11 - m01 * m10)
        {
        }

        void solve(Numbers& g) const
        {
            const double gvx = (m11 * g[2] - m01 * g[3]) / det;
            const double gvy = (m00 * g[3] - m10 * g[2]) / det;
            g = {(g[0] + gvx) / c, (g[1] + gvy) / c, gvx, gvy};
        }
    };

    static Numbers numbersOf(const FlightState& s) { return {s.position.x, s.position.y, s.velocity.x, s.velocity.y}; }
    static FlightState stateOf(const Numbers& n) { return {{n[0], n[1]}, {n[2], n[3]}}; }

    template <class Deriv>
    static Numbers slope(Deriv& deriv, const Numbers& x, double t)
    {
        FlightState dxdt{};
        deriv(stateOf(x), dxdt, t);
        return numbersOf(dxdt);
    }

    template <class Deriv, class Jacobian>
    static void step(Deriv& deriv, Jacobian& jacobian, const FlightState& state, double t, double dt,
                     FlightState& stateOut, FlightState& stateErr)
    {
        const Numbers x = numbersOf(state);
        const Numbers dxdt = slope(deriv, x, t);
        std::array<double, 4> a{};
        Vec2 dadt{};
        jacobian(state, t, a, dadt);
        const Numbers dfdt{0.0, 0.0, dadt.x, dadt.y};
        const StageSolver solver(1.0 / (kGamma * dt), a);

        Numbers g1{}, g2{}, g3{}, g4{}, g5{}, tmp{}, f{}, xErr{};
        for (std::size_t i = 0; i < 4; ++i)
            g1[i] = dxdt[i] + dt * kD1 * dfdt[i];
        solver.solve(g1);

        for (std::size_t i = 0; i < 4; ++i)
            tmp[i] = x[i] + kA21 * g1[i];
        f = slope(deriv, tmp, t + kC2 * dt);
        for (std::size_t i = 0; i < 4; ++i)
            g2[i] = f[i] + dt * kD2 * dfdt[i] + kC21 * g1[i] / dt;
        solver.solve(g2);

        for (std::size_t i = 0; i < 4; ++i)
            tmp[i] = x[i] + kA31 * g1[i] + kA32 * g2[i];
        f = slope(deriv, tmp, t + kC3 * dt);
        for (std::size_t i = 0; i < 4; ++i)
            g3[i] = f[i] + dt * kD3 * dfdt[i] + (kC31 * g1[i] + kC32 * g2[i]) / dt;
        solver.solve(g3);

        for (std::size_t i = 0; i < 4; ++i)
            tmp[i] = x[i] + kA41 * g1[i] + kA42 * g2[i] + kA43 * g3[i];
        f = slope(deriv, tmp, t + kC4 * dt);
        for (std::size_t i = 0; i < 4; ++i)
            g4[i] = f[i] + dt * kD4 * dfdt[i] + (kC41 * g1[i] + kC42 * g2[i] + kC43 * g3[i]) / dt;
        solver.solve(g4);

        for (std::size_t i = 0; i < 4; ++i)
            tmp[i] = x[i] + kA51 * g1[i] + kA52 * g2[i] + kA53 * g3[i] + kA54 * g4[i];
        f = slope(deriv, tmp, t + dt);
        for (std::size_t i = 0; i < 4; ++i)
            g5[i] = f[i] + (kC51 * g1[i] + kC52 * g2[i] + kC53 * g3[i] + kC54 * g4[i]) / dt;
        solver.solve(g5);

        for (std::size_t i = 0; i < 4; ++i)
            tmp[i] += g5[i];
        f = slope(deriv, tmp, t + dt);
        for (std::size_t i = 0; i < 4; ++i)
            xErr[i] = f[i] + (kC61 * g1[i] + kC62 * g2[i] + kC63 * g3[i] + kC64 * g4[i] + kC65 * g5[i]) / dt;
        solver.solve(xErr);

        Numbers xOut{};
        for (std::size_t i = 0; i < 4; ++i)
            xOut[i] = tmp[i] + xErr[i];
        stateOut = stateOf(xOut);
        stateErr = stateOf(xErr);
    }

    /// Root-mean-square error relative to atol + rtol |x|, as odeint's controller measures it.
    static double errorNorm(const FlightState& stateOld, const FlightState& state, const FlightState& stateErr,
                            double tol)
    {
        const Numbers xOld = numbersOf(stateOld);
        const Numbers x = numbersOf(state);
        const Numbers xErr = numbersOf(stateErr);
        double sum = 0.0;
        for (std::size_t i = 0; i < 4; ++i)
        {
            const double scale = tol + tol * std::max(std::abs(xOld[i]), std::abs(x[i]));
            sum += xErr[i] * xErr[i] / (scale * scale);
        }
        const double err = std::sqrt(sum / 4.0);
        return std::isfinite(err) ? err : 1e10;
    }

    double m_dtHint = 0.0;
    double m_dtOld = 0.0;
    double m_errOld = 0.0;
    bool m_lastRejected = false;
};

} // namespace abalike::detail
