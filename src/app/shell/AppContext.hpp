#pragma once

namespace abalike::app
{

class Navigator;
class Notices;
class PlayerProgress;
class PlayerSettings;
class RunControl;
class Trace;
class UiMetrics;

/// What screens and play layers are given: the application's parts, each with its own interface (where the player
/// goes, how text is sized, settings, progress, notices, the trace, the run). The window and the frame loop are not
/// among them: App owns those and assembles the parts.
class AppContext
{
public:
    AppContext(Navigator& navigator, UiMetrics& ui, PlayerSettings& settings, PlayerProgress& progress,
               Notices& notices, Trace& trace, RunControl& run)
        : m_navigator(navigator), m_ui(ui), m_settings(settings), m_progress(progress), m_notices(notices),
          m_trace(trace), m_run(run)
    {
    }

    Navigator& navigator() const { return m_navigator; }
    UiMetrics& ui() const { return m_ui; }
    PlayerSettings& settings() const { return m_settings; }
    PlayerProgress& progress() const { return m_progress; }
    Notices& notices() const { return m_notices; }
    Trace& trace() const { return m_trace; }
    RunControl& run() const { return m_run; }

private:
    Navigator& m_navigator;
    UiMetrics& m_ui;
    PlayerSettings& m_settings;
    PlayerProgress& m_progress;
    Notices& m_notices;
    Trace& m_trace;
    RunControl& m_run;
};

} // namespace abalike::app
