#pragma once

#include <abalike/flight/FlightState.hpp>
#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>

namespace abalike
{

/// odeint's algebra for FlightState: each of odeint's operations (its default_operations: scale sums and the like)
/// applied to the state's four numbers one after the other, position.x, position.y, velocity.x, velocity.y. That is
/// what odeint's array_algebra did while the state was an array of those four numbers, so every integrator does the
/// same floating-point operations in the same order. (A range over the members through an iterator did too, but
/// made RK4 two to four times slower: the compiler did not see through the iterator's choice of member.)
struct FlightStateAlgebra
{
    // Inlined always: the stages call it once per operation, and a call costs more than the four operations.
    template <class Op, class... States>
    [[gnu::always_inline]] static inline void each(Op& op, States&... states)
    {
        op(states.position.x...);
        op(states.position.y...);
        op(states.velocity.x...);
        op(states.velocity.y...);
    }

    template <class S1, class Op>
    [[gnu::always_inline]] static void for_each1(S1& s1, Op op)
    {
        each(op, s1);
    }
    template <class S1, class S2, class Op>
    [[gnu::always_inline]] static void for_each2(S1& s1, S2& s2, Op op)
    {
        each(op, s1, s2);
    }
    template <class S1, class S2, class S3, class Op>
    [[gnu::always_inline]] static void for_each3(S1& s1, S2& s2, S3& s3, Op op)
    {
        each(op, s1, s2, s3);
    }
    template <class S1, class S2, class S3, class S4, class Op>
    [[gnu::always_inline]] static void for_each4(S1& s1, S2& s2, S3& s3, S4& s4, Op op)
    {
        each(op, s1, s2, s3, s4);
    }
    template <class S1, class S2, class S3, class S4, class S5, class Op>
    [[gnu::always_inline]] static void for_each5(S1& s1, S2& s2, S3& s3, S4& s4, S5& s5, Op op)
    {
        each(op, s1, s2, s3, s4, s5);
    }
    template <class S1, class S2, class S3, class S4, class S5, class S6, class Op>
    [[gnu::always_inline]] static void for_each6(S1& s1, S2& s2, S3& s3, S4& s4, S5& s5, S6& s6, Op op)
    {
        each(op, s1, s2, s3, s4, s5, s6);
    }
    template <class S1, class S2, class S3, class S4, class S5, class S6, class S7, class Op>
    [[gnu::always_inline]] static void for_each7(S1& s1, S2& s2, S3& s3, S4& s4, S5& s5, S6& s6, S7& s7, Op op)
    {
        each(op, s1, s2, s3, s4, s5, s6, s7);
    }
    template <class S1, class S2, class S3, class S4, class S5, class S6, class S7, class S8, class Op>
    [[gnu::always_inline]] static void for_each8(S1& s1, S2& s2, S3& s3, S4& s4, S5& s5, S6& s6, S7& s7, S8& s8, Op op)
    {
        each(op, s1, s2, s3, s4, s5, s6, s7, s8);
    }

    /// The largest magnitude of the four numbers (odeint's error checkers).
    static double norm_inf(const FlightState& s)
    {
        double largest = 0.0;
        for (const double x : {s.position.x, s.position.y, s.velocity.x, s.velocity.y})
            largest = std::max(largest, std::abs(x));
        return largest;
    }
};

/// The steppers the flight uses, all on FlightStateAlgebra.
using FlightRk4 = boost::numeric::odeint::runge_kutta4<FlightState, double, FlightState, double, FlightStateAlgebra>;
using FlightEuler = boost::numeric::odeint::euler<FlightState, double, FlightState, double, FlightStateAlgebra>;
using FlightDopri5 =
    boost::numeric::odeint::runge_kutta_dopri5<FlightState, double, FlightState, double, FlightStateAlgebra>;

} // namespace abalike
