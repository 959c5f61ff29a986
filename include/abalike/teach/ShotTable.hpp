#pragma once

#include <abalike/game/GameSession.hpp>
#include <string>
#include <vector>

namespace abalike
{

/// The shots' flights as CSV for a spreadsheet, one row per physics step (1/60 s) of each shot's bird from launch
/// until it rests or leaves, under the header
/// shot,t_s,x_m,y_m,vx_mps,vy_mps,ax_mps2,ay_mps2,speed_mps,kinetic_j,potential_j,drag_work_j
/// shot counts from 1; t_s is time since that shot's launch; velocities and accelerations are central differences of
/// the flown positions (so they include the collisions after the first contact); potential_j is m g y with y in level
/// coordinates, as in `simulate --json`; drag_work_j is the work done against drag and wind since launch (J, the
/// energy the air took), integrated from the flight model along the flown path.
std::string shotTableCsv(const GameSession& session);

} // namespace abalike
