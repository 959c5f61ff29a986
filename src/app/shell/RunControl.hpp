#pragma once

#include "input/InputState.hpp"
#include "shell/AppOptions.hpp"
#include "shell/FrameTimes.hpp"

#include <vector>

namespace abalike::app
{

/// How this run was asked to go (`abalike play`'s options), the keys and buttons held now, and the frame clock:
/// what a screen needs to know of the run beyond its own state.
class RunControl
{
public:
    explicit RunControl(const AppOptions& options) : m_options(options) {}

    const AppOptions& options() const { return m_options; }
    /// True when scripted (--frames, --script, --shot): the player's files are read but never written.
    bool scripted() const { return m_options.scripted(); }
    /// The run's `--shot`s, once: they belong to the level the run opened on, so a level reached later (the next
    /// one after a win, a pack's next level) fires none.
    std::vector<ScriptedShot> takeScriptedShots();

    const InputState& input() const { return m_input; }
    InputState& input() { return m_input; }
    /// This frame's times so far: a screen adds the preview's share (`bench frames`).
    FrameTimes& frameTimes() { return m_frameTimes; }
    /// Frames drawn so far, counting from 1 for the first.
    long long frame() const { return m_frame; }
    /// Starts the next frame: counts it and clears its times.
    void startFrame();
    /// Seconds of one physics step.
    double stepSeconds() const { return kStepS; }

    static constexpr double kStepS = 1.0 / 60.0;

private:
    const AppOptions& m_options;
    bool m_shotsTaken = false;
    InputState m_input;
    FrameTimes m_frameTimes;
    long long m_frame = 0;
};

} // namespace abalike::app
