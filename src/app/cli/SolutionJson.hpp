#pragma once

#include <abalike/design/Solver.hpp>

#include <nlohmann/json.hpp>

namespace abalike::app
{

/// `{"level", "won", "score", "stars", "seconds", "shots": [{"angle_deg", "speed", "ability_at_s"}], ...}`: the
/// shots reproduce the score when fed to `abalike simulate`.
nlohmann::ordered_json solutionToJson(const LevelDef& level, const Solution& solution);

/// The shots as `--shot` arguments for `abalike simulate` ("ANGLE,SPEED" or "ANGLE,SPEED,ABILITY_AT_S").
std::string shotArguments(const std::vector<ScriptedShot>& shots);

} // namespace abalike::app
