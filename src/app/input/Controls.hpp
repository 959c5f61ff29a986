#pragma once

#include <string>
#include <vector>

namespace abalike::app
{

/// One row of the controls table: what the player wants to do, and how with the keyboard, the mouse and a gamepad.
/// The help overlay (F1 or ?) and the README's controls table are both this table (a test compares them).
struct ControlBinding
{
    std::string where;   ///< "Aiming", "In flight", "Anywhere", "Menus", ...
    std::string action;  ///< "Angle up / down"
    std::string keys;    ///< "Up / Down (Shift: 5° steps)"
    std::string mouse;   ///< "drag the bird"
    std::string gamepad; ///< "left stick or D-pad"; empty when a gamepad has no way
};

/// Every control of the game, grouped by where it applies.
const std::vector<ControlBinding>& controlTable();

/// The table as the README prints it: a Markdown table with a row per binding, the group in the first column.
std::string controlTableMarkdown();

} // namespace abalike::app
