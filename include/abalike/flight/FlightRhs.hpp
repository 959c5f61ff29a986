#pragma once

#include <abalike/flight/FlightModel.hpp>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

namespace abalike
{

/// Right-hand side of the flight ODE, compiled for one set of terms. Absent terms cost nothing:
/// FlightRhs<kGravityTerm> is d(x, y, vx, vy)/dt = (vx, vy, 0, -g), with no branch or multiply for drag or wind.
template <unsigned Terms>
class FlightRhs
{
public:
    static constexpr unsigned kTerms = Terms;
    static constexpr bool kHasDrag = (Terms & (kLinearDragTerm | kQuadraticDragTerm)) != 0;

    explicit FlightRhs(const FlightModel& model)
        : m_gravity(model.gravity), m_linearPerMass(model.linearDrag / model.massKg),
          m_quadraticPerMass(model.quadraticDrag / model.massKg), m_windX(model.windX), m_windY(model.windY),
          m_gusts(model.gusts ? &*model.gusts : nullptr)
    {
        if (m_gusts != nullptr && m_gusts->kind == GustDef::Kind::Sine)
        {
            m_sineGust = true;
            m_gustOmega = 2.0 * std::numbers::pi / m_gusts->periodS;
        }
    }

    void operator()(const FlightState& s, FlightState& dsdt, double t) const
    {
        dsdt.position = s.velocity;
        double ax = 0.0;
        double ay = 0.0;
        if constexpr ((Terms & kGravityTerm) != 0)
            ay = -m_gravity;
        if constexpr (kHasDrag)
        {
            // Drag acts on the velocity relative to the air.
            const auto [rx, ry] = relativeVelocity(s, t);
            if constexpr ((Terms & kLinearDragTerm) != 0)
            {
                ax -= m_linearPerMass * rx;
                ay -= m_linearPerMass * ry;
            }
            if constexpr ((Terms & kQuadraticDragTerm) != 0)
            {
                const double k = m_quadraticPerMass * std::sqrt(rx * rx + ry * ry);
                ax -= k * rx;
                ay -= k * ry;
            }
        }
        else
        {
            (void)t;
        }
        dsdt.velocity = {ax, ay};
    }

    /// Estimate of the largest |eigenvalue| of the velocity Jacobian: (b + 2 c |v - w|) / m (1/s).
    double stiffness(const FlightState& s, double t) const
    {
        if constexpr (!kHasDrag)
        {
            (void)s;
            (void)t;
            return 0.0;
        }
        else
        {
            double lambda = 0.0;
            if constexpr ((Terms & kLinearDragTerm) != 0)
                lambda += m_linearPerMass;
            if constexpr ((Terms & kQuadraticDragTerm) != 0)
            {
                const auto r = relativeVelocity(s, t);
                lambda += 2.0 * m_quadraticPerMass * std::sqrt(r.x * r.x + r.y * r.y);
            }
            return lambda;
        }
    }

    /// For implicit steppers: the Jacobian of the acceleration with respect to the velocity (row-major 2 x 2) and
    /// the acceleration's explicit rate of change in time (non-zero only with smooth gusts).
    void accelerationJacobian(const FlightState& s, double t, std::array<double, 4>& dadv, Vec2& dadt) const
    {
        dadv = {0.0, 0.0, 0.0, 0.0};
        dadt = {0.0, 0.0};
        if constexpr (kHasDrag)
        {
            if constexpr ((Terms & kLinearDragTerm) != 0)
            {
                dadv[0] -= m_linearPerMass;
                dadv[3] -= m_linearPerMass;
            }
            if constexpr ((Terms & kQuadraticDragTerm) != 0)
            {
                // a = -k |r| r  =>  da/dv = -k (|r| I + r r^T / |r|)
                const auto r = relativeVelocity(s, t);
                const double speed = std::sqrt(r.x * r.x + r.y * r.y);
                if (speed > 0.0)
                {
                    dadv[0] -= m_quadraticPerMass * (speed + r.x * r.x / speed);
                    dadv[1] -= m_quadraticPerMass * r.x * r.y / speed;
                    dadv[2] -= m_quadraticPerMass * r.y * r.x / speed;
                    dadv[3] -= m_quadraticPerMass * (speed + r.y * r.y / speed);
                }
            }
            if constexpr ((Terms & kGustTerm) != 0)
            {
                // a depends on t only through r = v - w(t): da/dt = -(da/dv) w'(t).
                const auto rate = m_gusts->rateAt(t);
                dadt.x = -(dadv[0] * rate.x + dadv[1] * rate.y);
                dadt.y = -(dadv[2] * rate.x + dadv[3] * rate.y);
            }
        }
        else
        {
            (void)s;
            (void)t;
        }
    }

private:
    /// Velocity relative to the air, v - w(t).
    Vec2 relativeVelocity(const FlightState& s, double t) const
    {
        Vec2 r = s.velocity;
        if constexpr ((Terms & kWindTerm) != 0)
        {
            r.x -= m_windX;
            r.y -= m_windY;
        }
        if constexpr ((Terms & kGustTerm) != 0)
        {
            if (m_sineGust)
            {
                // Inline rather than through GustDef::windAt: a returned pair costs a store-forwarding stall here.
                const double sine = std::sin(m_gustOmega * t + m_gusts->phaseRad);
                r.x -= m_gusts->amplitudeX * sine;
                r.y -= m_gusts->amplitudeY * sine;
            }
            else
            {
                const Vec2 gust = m_gusts->windAt(t);
                r.x -= gust.x;
                r.y -= gust.y;
            }
        }
        else
        {
            (void)t;
        }
        return r;
    }

    double m_gravity;
    double m_linearPerMass;
    double m_quadraticPerMass;
    double m_windX;
    double m_windY;
    const GustDef* m_gusts; // owned by the FlightModel, which must outlive this functor
    bool m_sineGust = false;
    double m_gustOmega = 0.0;
};

namespace detail
{
template <unsigned Mask, class Visitor>
decltype(auto) visitFlightRhs(unsigned terms, const FlightModel& model, Visitor&& visitor)
{
    if constexpr (Mask == kAllFlightTerms)
        return std::forward<Visitor>(visitor)(FlightRhs<Mask>(model));
    else
    {
        if (terms == Mask)
            return std::forward<Visitor>(visitor)(FlightRhs<Mask>(model));
        return visitFlightRhs<Mask + 1>(terms, model, std::forward<Visitor>(visitor));
    }
}
} // namespace detail

/// Calls visitor(FlightRhs<T>) with T = activeTerms(model): the terms are chosen once, here, not on every evaluation.
template <class Visitor>
decltype(auto) visitFlightRhs(const FlightModel& model, Visitor&& visitor)
{
    return detail::visitFlightRhs<0>(activeTerms(model), model, std::forward<Visitor>(visitor));
}

} // namespace abalike
