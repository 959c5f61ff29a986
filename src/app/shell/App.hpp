#pragma once

#include "input/Gamepad.hpp"
#include "input/ScriptedInput.hpp"
#include "shell/AppContext.hpp"
#include "shell/AppOptions.hpp"
#include "shell/FrameLayout.hpp"
#include "shell/Navigator.hpp"
#include "shell/Notices.hpp"
#include "shell/PlayerProgress.hpp"
#include "shell/PlayerSettings.hpp"
#include "shell/RunControl.hpp"
#include "shell/Trace.hpp"
#include "shell/UiMetrics.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/System/Clock.hpp>
#include <abalike/level/Campaign.hpp>
#include <abalike/save/SaveStore.hpp>
#include <memory>
#include <optional>

namespace abalike::app
{

/// The game application: the window and the fixed-step loop, and the parts every screen is given (AppContext:
/// navigation, text metrics, settings, progress, notices, the trace, the run), which it assembles.
///
/// Each frame: the script's events for this frame, then the window's events, go to the top screen through the same
/// path; the physics steps due (exactly one 1/60 s step per frame in an offline run with --frames, otherwise from
/// an accumulator capped at 0.25 s) go to the top screen; then it draws the stack, and only after the frame are
/// screen changes applied.
class App
{
public:
    /// store: the player's files, already loaded (its messages are shown once the game runs).
    App(AppOptions options, Campaign campaign, SaveStore store, std::unique_ptr<sf::Font> font);
    ~App();

    /// Opens the first screen and plays until the window closes, quit() is called, or the frame budget is spent.
    /// Returns the exit code.
    int run();

    /// What the screens are given.
    AppContext& context() { return m_context; }

    static constexpr double kStepS = RunControl::kStepS;

private:
    void openWindow();
    /// Opens the window again for a new saved size or full screen, and tells every screen.
    void reopenWindow();
    void settingsApplied(const Settings& before, const Settings& after);
    void openFirstScreen();
    void dispatch(const sf::Event& event);
    /// Opens the help (F1 or '?'); on the help itself those keys are the help screen's, which closes.
    void toggleHelp();
    bool helpOnTop() const;
    /// True when the app handled the event itself (window close, resize, global keys).
    bool handleGlobal(const sf::Event& event);
    /// One frame: events, the physics steps due, the frame update, then drawing (or laying out, every layoutEvery
    /// frames when the observer asks for it). True when it was a scripted run's last frame.
    bool runFrame(sf::Clock& clock, int layoutEvery);
    /// After the loop: the last frame recorded for the observer, the trace or the screenshot. Returns the exit code.
    int finishRun(int exitCode, bool layoutOnly);
    int stepsForFrame(double frameS);
    /// reuseCovered: screens under an overlay come from the stack's copy of them (ScreenStack::drawWithSnapshot);
    /// false draws every screen, as the last frame of a scripted run does to record its texts and panels.
    void drawFrame(bool reuseCovered = false);
    /// Draws every screen (pixels: false lays the frame out without drawing a pixel) and returns where its panels
    /// went and what they should leave visible.
    FrameLayout recordFrame(bool pixels);
    ScreenStack& screens() { return m_navigator.screens(); }

    AppOptions m_options;
    std::unique_ptr<sf::Font> m_font;
    sf::RenderWindow m_ownWindow;
    sf::RenderWindow& m_window; ///< m_ownWindow, or the one AppOptions::window lends
    std::optional<SaveStore> m_store;
    Trace m_trace;
    Notices m_notices;
    PlayerSettings m_settings;
    PlayerProgress m_progress;
    UiMetrics m_ui;
    Navigator m_navigator;
    RunControl m_run;
    AppContext m_context;
    GamepadTranslator m_gamepad;
    ScriptedInput m_script;
    long long m_offlineSteps = 0;
    double m_accumulator = 0.0;
};

} // namespace abalike::app
