#pragma once

#include <abalike/game/GameSession.hpp>

#include <nlohmann/json.hpp>

namespace abalike::app
{

/// The `abalike simulate --json` document for a finished (or stopped) session.
nlohmann::ordered_json sessionToJson(const GameSession& session);

} // namespace abalike::app
