#pragma once

#include "input/Gamepad.hpp"
#include "input/InputState.hpp"
#include "input/ScriptedInput.hpp"
#include "shell/AppOptions.hpp"
#include "shell/ScreenStack.hpp"
#include "shell/Trace.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/System/Clock.hpp>
#include <abalike/level/Campaign.hpp>
#include <abalike/level/LevelDef.hpp>
#include <abalike/save/SaveStore.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

class EndlessGame;

/// The game application: the window, the fixed-step loop, the screen stack and what every screen shares (font,
/// input, settings, saved progress, the campaign). Screens hold an App& and ask it for these.
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

    const AppOptions& options() const { return m_options; }
    /// The run's `--shot`s, once: they belong to the level the run opened on, so a level reached later (the next
    /// one after a win, a pack's next level) fires none.
    std::vector<ScriptedShot> takeScriptedShots();
    sf::RenderWindow& window() { return m_window; }
    sf::Vector2u windowSize() const { return m_window.getSize(); }
    /// Null when no font could be loaded; screens then draw without text.
    const sf::Font* font() const { return m_font.get(); }
    ScreenStack& screens() { return m_screens; }
    const InputState& input() const { return m_input; }
    Trace& trace() { return m_trace; }
    /// This frame's times so far: a screen adds the preview's share (`bench frames`).
    FrameTimes& frameTimes() { return m_frameTimes; }
    /// Frames drawn so far, counting from 1 for the first.
    long long frame() const { return m_frame; }
    /// Seconds of one physics step.
    double stepSeconds() const { return kStepS; }

    const Campaign& campaign() const { return m_campaign; }
    /// True when scripted (--frames, --script, --shot): the player's files are read but never written.
    bool scripted() const { return m_options.scripted(); }

    const Settings& settings() const { return m_settings; }
    /// School or university: --wording for this run, else the setting.
    Wording wording() const { return m_options.wording.value_or(m_settings.wording); }
    bool universityWording() const { return wording() == Wording::University; }
    /// Game or learn: what the player last chose on the title screen, else --mode, else the setting.
    PlayMode mode() const { return m_mode.value_or(m_options.mode.value_or(m_settings.mode)); }
    /// The player chose a mode (the title's Play or Learn): it holds for the run and is saved (not in scripted runs).
    void setMode(PlayMode mode);
    /// True when --size set the window on the command line: the saved size and full screen do not apply.
    bool sizeFromCommandLine() const { return m_options.width.has_value(); }
    /// Applies new settings (the look, the window's size and full screen) and saves them (not in scripted runs).
    void updateSettings(const Settings& settings);
    const Progress& progress() const { return m_progress; }
    /// Records a finished level (best score and stars, unlocks the next) and saves it (not in scripted runs).
    void recordResult(const std::string& levelId, int score, int stars);
    /// The endless mode of this session, started (its worker with it) the first time it is asked for.
    EndlessGame& endless();
    /// The endless run has won `levelsWon` levels for `score` points (ended: the run is over, lost): keeps the
    /// player's bests and saves them (not in scripted runs).
    void recordEndless(int levelsWon, int score, bool ended);
    /// Whether the player may start this campaign level.
    bool isUnlocked(const std::string& levelId) const;

    /// A one-line message for the player, shown for a few seconds over every screen (and printed on stderr).
    void notify(const std::string& message);
    /// A notice about one setting (topic: "speed", "overlay", ...): it replaces that setting's earlier notice, so
    /// pressing a key twice never shows "Speed 1/2x" and "Speed 1/4x" at once.
    void notify(const std::string& message, const std::string& topic);
    /// Queues an input event to go through the same path as the player's at the start of the next frame: a toolbar
    /// button presses the key it stands for.
    void post(const sf::Event& event) { m_posted.push_back(event); }
    /// Ends the run after this frame with this exit code.
    void quit(int exitCode = 0);

    /// UI text size multiplier: the window's size against 1280x720 times the player's text scale.
    float uiScale() const;
    /// Point size for UI text of a nominal size at 1280x720 and 100 % text scale.
    unsigned textSize(float nominal) const;

    static constexpr double kStepS = 1.0 / 60.0;

private:
    void openWindow();
    /// Opens the window again for a new saved size or full screen, and tells every screen.
    void reopenWindow();
    void openFirstScreen();
    void dispatch(const sf::Event& event);
    void toggleHelp();
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
    void drawNotices();
    void takeStoreMessages();

    AppOptions m_options;
    bool m_shotsTaken = false;
    Campaign m_campaign;
    std::unique_ptr<sf::Font> m_font;
    sf::RenderWindow m_ownWindow;
    sf::RenderWindow& m_window; ///< m_ownWindow, or the one AppOptions::window lends
    ScreenStack m_screens;
    InputState m_input;
    GamepadTranslator m_gamepad;
    std::vector<sf::Event> m_posted;
    ScriptedInput m_script;
    Trace m_trace;
    FrameTimes m_frameTimes;
    std::optional<SaveStore> m_store;
    Settings m_settings;
    Progress m_progress;
    std::unique_ptr<EndlessGame> m_endless;

    struct Notice
    {
        std::string text;
        double shownS = 0.0;
        std::string topic; ///< empty: stands on its own
    };
    std::vector<Notice> m_notices;

    std::optional<PlayMode> m_mode; ///< chosen in this run
    long long m_frame = 0;
    long long m_offlineSteps = 0;
    double m_accumulator = 0.0;
    std::optional<int> m_exitCode;
};

} // namespace abalike::app
