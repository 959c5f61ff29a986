#pragma once

#include <abalike/game/GameSession.hpp>
#include <abalike/world/Ability.hpp>

#include <vector>

namespace abalike
{

/// A moment of a shot's free flight to drop a payload so that it lands on a pig still standing after the shot.
struct DropAim
{
    int pig = -1;         ///< the pig's index in the level
    double atS = 0.0;     ///< seconds after launch
    double blowMps = 0.0; ///< the payload's downward speed where it reaches the pig's top (no air)
};

/// Where the last shot of session flew over a standing pig: for each pig, the moments (before the bird's first
/// contact) at which the payload, let go, lands on its top, in vacuum under the level's gravity. The drop's
/// ballistics are an estimate for the solver to try, never a result: the world plays each try in full.
std::vector<DropAim> dropAims(const GameSession& session, const DroppedPayload& payload);

} // namespace abalike
