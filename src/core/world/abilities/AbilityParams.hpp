#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>

namespace abalike
{

/// A number of an ability's block in the catalog: fallback when absent; throws std::runtime_error unless > 0.
double abilityNumber(const nlohmann::json& params, const char* key, double fallback, std::string_view ability);

/// A number with a fixed count of decimals, for the catalog's table.
std::string fixedDecimals(double value, int decimals);

} // namespace abalike
