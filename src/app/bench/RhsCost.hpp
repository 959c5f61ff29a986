#pragma once

#include <string>
#include <vector>

namespace abalike::app
{

/// What one scene's right-hand side and preview cost.
struct RhsCost
{
    std::string scene;
    std::string terms;        ///< the active terms, as predict's JSON names them
    double composedNs = 0.0;  ///< one evaluation of FlightRhs<terms> (median)
    double branchingNs = 0.0; ///< the same forces by a right-hand side that tests every term on every call
    double previewUs = 0.0;   ///< predictFlight, RK4 at 60 Hz, launch to landing (median)
    std::size_t previewSteps = 0;
    double sessionPreviewUs = 0.0; ///< GameSession::preview in a level: the same plus contact queries (median)
};

/// Gravity only; gravity + quadratic drag + wind; every term (linear drag and sine gusts as well).
std::vector<RhsCost> measureRhsCost(bool quick);

} // namespace abalike::app
