#pragma once

#include <abalike/game/GameSession.hpp>
#include <string>
#include <vector>

namespace abalike
{

/// The shots' flights as CSV for a spreadsheet, one row per physics step (1/60 s) of each shot's bird from launch
/// until it rests or leaves, under the header
/// shot,t_s,x_m,y_m,vx_mps,vy_mps,ax_mps2,ay_mps2,speed_mps,kinetic_j,potential_j,drag_work_j,contact,contact_acts
/// shot counts from 1; t_s is time since that shot's launch. Until the first contact (or an ability that changes the
/// flight) the rows are the RK4 flight the world flies, in double precision: state, the model's acceleration and the
/// exact work against drag. After it, velocities are central differences of the flown positions; contact_acts is 1
/// on a row whose differences span a step in which the bird touched something, and only there is the acceleration
/// measured (the change of that velocity over the step ending at the row, so a row through a collision carries it);
/// every other row gives the flight model's acceleration (-g in vacuum). The last row is a whole step: a row that
/// would need the step after it is left out. The drag work goes on by the trapezoid rule. potential_j is m g y with
/// y in level coordinates, as in `simulate --json`; drag_work_j is the energy the air took since launch (J); contact
/// names what the bird touched in the step ending at the row ("block 3 wood", "pig 0 small", "ground", several
/// joined by " + "; empty if none).
std::string shotTableCsv(const GameSession& session);

} // namespace abalike
