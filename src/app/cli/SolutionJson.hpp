#pragma once

#include <abalike/design/ModelPlayer.hpp>
#include <abalike/design/Solver.hpp>

#include <nlohmann/json.hpp>

namespace abalike::app
{

/// `{"level", "won", "score", "stars", "seconds", "shots": [{"angle_deg", "speed", "ability_at_s"}], ...}`: the
/// shots reproduce the score when fed to `abalike simulate`.
nlohmann::ordered_json solutionToJson(const LevelDef& level, const Solution& solution);

/// The shots as `--shot` arguments for `abalike simulate` ("ANGLE,SPEED" or "ANGLE,SPEED,ABILITY_AT_S").
std::string shotArguments(const std::vector<ScriptedShot>& shots);

/// {"runs", "wins", "win_share", "low90", "high90", "simulations", "seconds"}
nlohmann::ordered_json playerDifficultyJson(const PlayerDifficulty& player);
/// "model player: 31 of 40 runs won (78 %, 90 % interval 65-86 %), 2 390 games in 12.0 s"
std::string playerDifficultyText(const PlayerDifficulty& player);

} // namespace abalike::app
