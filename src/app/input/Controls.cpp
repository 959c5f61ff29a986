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
        {"Teaching", "Teaching overlay: forces, energy, impact, timing dots", "T", ""},
        {"Teaching", "Read a path point (t, x, y, speed, height)", "", "point at it; click to pin when no bird flies"},
        {"Teaching", "Tape measure", "", "drag with the right button"},
        {"Teaching", "Clear the kept paths and the tape", "C", ""},
        {"Teaching", "Range-by-angle chart", "G", ""},
        {"Teaching", "Integrator comparison: next method, step", "I, then [ and ]", ""},
        {"Teaching", "RK4 walkthrough: start, next step, step size, leave", "K, Space, [ and ], Esc", ""},
        {"Anywhere", "This help", "F1 or ?", ""},
        {"Menus", "Choose", "Up / Down, Tab", "point"},
        {"Menus", "Confirm", "Enter or Space", "click"},
        {"Menus", "Back", "Esc", ""},
    };
    return table;
}

} // namespace abalike::app
