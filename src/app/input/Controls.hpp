#pragma once

#include <string>
#include <vector>

namespace abalike::app
{

/// One row of the controls table: what the player wants to do, and how with the keyboard and with the mouse.
/// The help overlay (F1 or ?) and the README's key table are both this table.
struct ControlBinding
{
    std::string where;  ///< "Aiming", "In flight", "Anywhere", "Menus", ...
    std::string action; ///< "Angle up / down"
    std::string keys;   ///< "Up / Down (Shift: coarse)"
    std::string mouse;  ///< "drag the bird"; empty when the mouse has no way
};

/// Every control of the game, grouped by where it applies.
const std::vector<ControlBinding>& controlTable();

} // namespace abalike::app
