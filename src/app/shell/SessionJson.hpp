#pragma once

#include <abalike/game/GameSession.hpp>

#include <nlohmann/json.hpp>

namespace abalike::app
{

/// One entry of simulate's "defeats" and play --trace's defeat event: {"t", "shot", "kind", "index", "cause"}.
nlohmann::ordered_json defeatJson(const DestroyedEvent& defeat);

/// The `abalike simulate --json` document for a finished (or stopped) session.
nlohmann::ordered_json sessionToJson(const GameSession& session);

} // namespace abalike::app
