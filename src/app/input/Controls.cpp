#include "input/Controls.hpp"

namespace abalike::app
{

const std::vector<ControlBinding>& controlTable()
{
    static const std::vector<ControlBinding> table{
        {"Aiming", "Angle up / down", "Up / Down", "drag the bird back: direction"},
        {"Aiming", "Power up / down", "Right / Left", "drag the bird back: distance"},
        {"Aiming", "Launch", "Space or Enter", "let go of the bird"},
        {"In flight", "Use the bird's ability", "Space", "click"},
        {"Playing", "Restart the level", "R", "pause menu: Restart"},
        {"Playing", "Next level (after a win)", "N", "results: Next level"},
        {"Playing", "Pause menu", "Esc or P", ""},
        {"Anywhere", "This help", "F1 or ?", ""},
        {"Menus", "Choose", "Up / Down, Tab", "point"},
        {"Menus", "Confirm", "Enter or Space", "click"},
        {"Menus", "Back", "Esc", ""},
    };
    return table;
}

} // namespace abalike::app
