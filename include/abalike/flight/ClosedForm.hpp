#pragma once

#include <abalike/flight/FlightModel.hpp>
#include <optional>

namespace abalike
{

/// True when the model's flight has a closed form: vacuum (gravity only), or linear drag with a constant wind.
/// Quadratic drag and gusts have none.
bool hasClosedForm(const FlightModel& model);

/// Exact state after flying for t seconds from s0 (the model is autonomous, so only elapsed time matters);
/// nullopt when the model has no closed form.
std::optional<FlightState> closedFormState(const FlightModel& model, const FlightState& s0, double t);

} // namespace abalike
