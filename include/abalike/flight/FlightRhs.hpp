#pragma once

#include <abalike/flight/FlightModel.hpp>

#include <cmath>
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
    }

    void operator()(const FlightState& s, FlightState& dsdt, double t) const
    {
        dsdt[0] = s[2];
        dsdt[1] = s[3];
        double ax = 0.0;
        double ay = 0.0;
        if constexpr ((Terms & kGravityTerm) != 0)
            ay = -m_gravity;
        if constexpr (kHasDrag)
        {
            // Drag acts on the velocity relative to the air.
            double rx = s[2];
            double ry = s[3];
            if constexpr ((Terms & kWindTerm) != 0)
            {
                rx -= m_windX;
                ry -= m_windY;
            }
            if constexpr ((Terms & kGustTerm) != 0)
            {
                const auto gust = m_gusts->windAt(t);
                rx -= gust[0];
                ry -= gust[1];
            }
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
        dsdt[2] = ax;
        dsdt[3] = ay;
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
                double rx = s[2];
                double ry = s[3];
                if constexpr ((Terms & kWindTerm) != 0)
                {
                    rx -= m_windX;
                    ry -= m_windY;
                }
                if constexpr ((Terms & kGustTerm) != 0)
                {
                    const auto gust = m_gusts->windAt(t);
                    rx -= gust[0];
                    ry -= gust[1];
                }
                lambda += 2.0 * m_quadraticPerMass * std::sqrt(rx * rx + ry * ry);
            }
            return lambda;
        }
    }

private:
    double m_gravity;
    double m_linearPerMass;
    double m_quadraticPerMass;
    double m_windX;
    double m_windY;
    const GustDef* m_gusts; // owned by the FlightModel, which must outlive this functor
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
