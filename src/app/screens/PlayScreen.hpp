#pragma once

#include "input/AimController.hpp"
#include "input/ShotScript.hpp"
#include "render/Camera.hpp"
#include "render/Hud.hpp"
#include "render/OverlayRenderer.hpp"
#include "render/ReloadNotice.hpp"
#include "render/ResultsPanel.hpp"
#include "render/WorldRenderer.hpp"
#include "screens/PlayOptions.hpp"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderWindow.hpp>
#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelWatcher.hpp>
#include <abalike/save/SaveStore.hpp>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace abalike::app
{

/// `abalike play`: a window over a sequence of levels. Physics runs in fixed steps from an accumulator; input
/// becomes aim and launch requests to the GameSession, which decides everything else.
class PlayScreen
{
public:
    PlayScreen(sf::RenderWindow& window, const PlayOptions& options, std::vector<LevelDef> levels,
               const sf::Font* font);

    /// Plays until the window closes, Escape, or the frame budget is spent. Returns the exit code.
    int run();

private:
    /// What the preview was computed for; a new key means the aim or the bird changed.
    struct PreviewKey
    {
        double angleDeg = 0.0;
        double speedMps = 0.0;
        int birdsUsed = -1;
        int generation = -1;
        bool operator==(const PreviewKey&) const = default;
    };

    void startLevel(std::size_t index);
    void restartLevel();
    /// Records a finished level in the player's progress once per play (interactive play only).
    void saveResultIfFinished();
    /// Forgets the aim, any pending launch and the preview (new level or restart).
    void resetAim();
    /// Polls window events; false when the player asked to quit.
    bool handleEvents();
    void handleKey(sf::Keyboard::Key key);
    bool playerMayAim() const;
    /// One fixed step: pending launches and abilities, scripted shots, then the world. An exit code when it must
    /// stop.
    std::optional<int> fixedStep();
    /// Fires the pending scripted shot once it has been shown long enough. An exit code when it cannot be fired.
    std::optional<int> fireScriptedShot();
    void syncScriptedAim();
    double aimSpeedMps() const;
    std::optional<AimReadout> aimReadout() const;
    void refreshPreview();
    void render();
    /// Live reload: a saved edit of the level file restarts the level; an invalid one keeps the last good version.
    void pollLevelFile();

    sf::RenderWindow& m_window;
    const PlayOptions& m_options;
    std::vector<LevelDef> m_levels;
    std::size_t m_levelIndex = 0;
    std::unique_ptr<GameSession> m_session;
    std::optional<SaveStore> m_store; ///< the player's progress; absent in scripted runs (--frames, --shot)
    bool m_resultSaved = false;
    int m_generation = 0;
    Camera m_camera;

    AimController m_aim;
    ShotScript m_script;
    std::optional<ScriptedShot> m_requestedLaunch;
    bool m_abilityRequested = false;
    std::optional<double> m_scriptAbilityAtS; ///< when the scripted shot in flight uses its bird's ability
    int m_scriptShotNumber = 0;
    std::optional<PredictedFlight> m_preview;
    PreviewKey m_previewKey;

    WorldRenderer m_world;
    OverlayRenderer m_overlay;
    Hud m_hud;
    ResultsPanel m_results;
    std::optional<LevelWatcher> m_watcher;
    std::vector<std::string> m_reloadErrors; ///< problems of the last edit that did not load
    ReloadNotice m_reloadNotice;
};

} // namespace abalike::app
