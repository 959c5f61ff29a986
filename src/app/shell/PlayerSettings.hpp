#pragma once

#include <abalike/save/Settings.hpp>
#include <functional>
#include <optional>

namespace abalike
{
class SaveStore;
}

namespace abalike::app
{

struct AppOptions;
class Notices;
class Trace;

/// The player's settings: as saved, with what the command line says for this run (`--wording`, `--mode`,
/// `--size`) on top. Changes are traced and saved (not in scripted runs).
class PlayerSettings
{
public:
    /// Called after new settings are applied, with the ones they replace (the app reopens the window for a new
    /// size and redraws the screens under the top one).
    using Applied = std::function<void(const Settings& before, const Settings& after)>;

    /// store may be null (no folder for saved games).
    PlayerSettings(const AppOptions& options, SaveStore* store, Trace& trace, Notices& notices);

    const Settings& current() const { return m_settings; }
    /// School or university: --wording for this run, else the setting.
    Wording wording() const;
    bool universityWording() const { return wording() == Wording::University; }
    /// Game or learn: what the player last chose on the title screen, else --mode, else the setting.
    PlayMode mode() const;
    /// The player chose a mode (the title's Play or Learn): it holds for the run and is saved (not in scripted runs).
    void setMode(PlayMode mode);
    /// True when --size set the window on the command line: the saved size and full screen do not apply.
    bool sizeFromCommandLine() const;
    /// Applies new settings (the look, the window's size and full screen) and saves them (not in scripted runs).
    void update(const Settings& settings);

    void onApplied(Applied applied) { m_applied = std::move(applied); }

private:
    const AppOptions& m_options;
    SaveStore* m_store;
    Trace& m_trace;
    Notices& m_notices;
    Settings m_settings;
    std::optional<PlayMode> m_mode; ///< chosen in this run
    Applied m_applied;
};

} // namespace abalike::app
