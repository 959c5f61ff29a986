#include "input/Controls.hpp"

namespace abalike::app
{

const std::vector<ControlBinding>& controlTable()
{
    // Keep the gamepad column in step with input/Gamepad.cpp and the toolbar column with screens/PlayToolbar.cpp.
    static const std::vector<ControlBinding> table{
        {"Aiming", "Angle up / down (0.5° steps; Shift: 5°; Alt: 0.1°)", "Up / Down", "drag the bird back: direction",
         "left stick or D-pad up / down (hold LB: 5°)"},
        {"Aiming", "Pull further / less (1 % steps; Shift: 10 %; Alt: 0.2 %)", "Right / Left",
         "drag the bird back: distance", "left stick or D-pad right / left (hold LB: 10 %)"},
        {"Aiming", "Launch", "Space or Enter", "let go of the bird", "A"},
        {"In flight", "Use the bird's ability", "Space or Enter", "click", "A"},
        {"In flight", "Fast-forward the flight until it touches something: 3\u00D7 (what you see only)", "F (hold)",
         "hold the \u00BB button", ""},
        {"Camera", "Zoom in / out", "+ / -", "wheel", "right stick up / down"},
        {"Camera", "Pan", "W A S D (Shift: further)", "drag on empty sky, or with the middle button", ""},
        {"Camera", "Back to the automatic camera", "Home or 0", "\u2302 button", "RB"},
        {"Playing", "Restart the level", "R", "Pause button, then Restart", "X"},
        {"Playing", "Next level (after a win)", "N", "results: Next level", "A on Next level"},
        {"Playing", "Pause menu", "Esc or P", "Pause button (top right)", "Start or B"},
        {"Teaching", "Teaching overlay: forces, energy, impact, timing dots", "T", "T button", "Y"},
        {"Teaching", "Read a path point (t, x, y, speed, height)", "M (again: older path), then , and . (Shift: 1 s)",
         "point at it; click to pin when no bird flies", ""},
        {"Teaching", "Tape measure", "L at a reading, move the reading, L to remove", "drag with the right button", ""},
        {"Teaching", "Clear the kept paths and the tape", "C", "C button", ""},
        {"Teaching", "Velocity components vx and vy beside v", "V", "V button", ""},
        {"Teaching", "Slow motion: real time, \u00BD, \u00BC (same physics)", "Z", "1\u00D7 button", ""},
        {"Teaching", "Export the level's shots as CSV (data folder's exports/)", "E", "\u21A7 button", ""},
        {"Teaching", "Range-by-angle chart", "G", "G button", ""},
        {"Teaching", "Integrator comparison: next method, step", "I, then [ and ]", "I button", ""},
        {"Teaching", "RK4 walkthrough: start, next step, step size, leave", "K, Space, [ and ], Esc", "K button", ""},
        {"Anywhere", "This help", "F1 or ?", "? button", "Back"},
        {"Menus", "Choose", "Up / Down, Tab", "point", "D-pad or left stick"},
        {"Menus", "Confirm", "Enter or Space", "click", "A"},
        {"Menus", "Back", "Esc", "right click", "B"},
        {"Menus", "Open the chosen level in the editor (level select)", "E",
         "title menu: Sandbox and editor, then File, Open", ""},
    };
    return table;
}

namespace
{
std::string cell(const std::string& text)
{
    if (text.empty())
        return "—";
    std::string out;
    for (char c : text)
    {
        // Brackets and pipes would be read as Markdown.
        if (c == '|' || c == '[' || c == ']')
            out += '\\';
        out += c;
    }
    return out;
}
} // namespace

std::string controlTableMarkdown()
{
    std::string out = "| where | action | keyboard | mouse | gamepad |\n|---|---|---|---|---|\n";
    for (const ControlBinding& row : controlTable())
        out += "| " + row.where + " | " + cell(row.action) + " | " + cell(row.keys) + " | " + cell(row.mouse) + " | " +
               cell(row.gamepad) + " |\n";
    return out;
}

} // namespace abalike::app
