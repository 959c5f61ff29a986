#pragma once

#include "endless/EndlessGame.hpp"
#include "play/FastForward.hpp"
#include "play/PlayField.hpp"
#include "render/Camera.hpp"
#include "render/CameraControls.hpp"
#include "render/CameraFocus.hpp"
#include "render/CameraRig.hpp"
#include "render/ReloadNotice.hpp"
#include "shell/Screen.hpp"

#include <abalike/game/GameSession.hpp>
#include <abalike/game/ShotSequence.hpp>
#include <abalike/level/LevelWatcher.hpp>
#include <chrono>
#include <cstddef>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

class AppContext;

/// The level a play screen plays and where it came from.
struct PlaySource
{
    LevelDef level;
    std::string path;                         ///< the file, watched for live reload; empty for a scene held in memory
    std::optional<std::size_t> campaignIndex; ///< its place in the campaign, so "next level" can follow
    std::optional<PlayMode> mode = std::nullopt; ///< Learn for the tutorial and the lessons; none: the app's mode
    std::optional<EndlessLevel> endless = std::nullopt; ///< a level of the endless run: its result goes to the run
};

/// Playing one level: aim, launch, watch. Physics runs in the App's fixed steps; input becomes aim and launch
/// requests to the GameSession, which decides everything else. Layers (PlayLayer) add what is drawn on top. The
/// aim, the preview and the steps are shared with the editor's play test (PlayField); this screen adds the camera,
/// scripted shots, results, live reload of the level file and the rest check's banner.
class PlayScreen : public Screen, public PlayField
{
public:
    static constexpr std::string_view kName = "play";

    PlayScreen(AppContext& app, PlaySource source);
    ~PlayScreen() override;

    std::string_view name() const override { return kName; }
    void handleEvent(const sf::Event& event) override;
    void fixedUpdate(double dtS) override;
    void frameUpdate(double frameS) override;
    void draw(sf::RenderTarget& target) override;
    void onResize(sf::Vector2u size) override;
    bool rightClickIsBack() const override { return false; }

    /// Starts the level again from its definition.
    void restartLevel();
    /// The next campaign level after this one, if there is one.
    std::optional<std::size_t> nextLevelIndex() const;
    /// Replaces this screen by the next campaign level (only after a win); in the endless mode, by the run's next.
    void goToNextLevel();
    bool endless() const { return m_source.endless.has_value(); }
    const PlaySource& source() const { return m_source; }

    // PlayView
    void finishBackgroundWork() override;
    bool changesWhileCovered() const override { return settling(); }
    PlayMode playMode() const override;
    std::string levelLabel() const override;
    const Camera& camera() const override { return m_rig.camera(); }
    const CameraRig& cameraRig() const { return m_rig; }
    void stepOnce() override;

protected:
    std::optional<double> scriptedSpeedMps() const override;

private:
    /// A new session of the level; withOpening: a level wider than the aiming view opens with the camera's pan.
    void startSession(bool withOpening);
    /// What the camera should keep in view now, below the panels on screen.
    CameraFocus cameraFocus() const;
    static constexpr float kTeachingTopReserved = 0.4f;
    /// The ground line never rises above this fraction of the window, however large the text at the bottom.
    static constexpr float kMostGroundFromBottom = 0.3f;
    /// Forgets the aim, any pending launch, the scripted ability and the preview (new level or restart).
    void resetShot();
    void handleKey(const sf::Event::KeyEvent& key);
    bool playerMayAim() const;
    /// One physics step: pending launches and abilities, scripted shots, then the world.
    void physicsStep();
    /// Fires the pending scripted shot once it has been shown long enough.
    /// Plays the script's part of one physics step; false when the world did not step (a shot's hold, or a shot
    /// that could not be fired).
    bool advanceScript();
    /// Writes each block broken and pig defeated since the last step to the trace as a "defeat" event.
    void traceDefeats();
    /// Starts the rest check of the level file as loaded on a worker thread (m_restFindings, for the banner).
    void findRestProblems();
    /// Takes the rest check's findings once it has finished (wait: until it has).
    void collectRestProblems(bool wait);
    /// Starts the session's settle step (its first step) on a worker thread in live play.
    void startSettling();
    /// Ends the settle step's worker once it has finished (wait: until it has).
    void finishSettling(bool wait);
    bool settling() const { return m_settling.valid(); }
    void drawSettleProgress(sf::RenderTarget& target) const;
    /// What the problems banner shows: the last edit's load errors, else the rest check's findings (or nothing).
    const std::vector<std::string>& bannerLines() const;
    const char* bannerHeading() const;
    void syncScriptedAim();
    /// Once the level is decided: record the result and show the results card.
    void finishIfDone();
    /// Live reload: a saved edit of the level file restarts the level; an invalid one keeps the last good version.
    void pollLevelFile();

    PlaySource m_source;
    bool m_finishHandled = false;
    std::size_t m_destroyedTraced = 0; ///< events of session.destroyed() already written to the trace
    FastForward m_fastForward;
    CameraRig m_rig; ///< fitted at start, follows the shot, returns when the world settles; the player pans and zooms
    CameraControls m_cameraControls;

    /// `--shot`: the timing `abalike simulate` uses; each shot's preview shows for kScriptedHoldS first, without
    /// the world moving, so the window replays what the headless run computes.
    ShotSequence m_script;
    static constexpr int kNoBirdAimed = -1;
    /// The bird the aim belongs to (game mode pulls each bird afresh, the first one too): none before the first.
    int m_aimedBird = kNoBirdAimed;

    std::optional<LevelWatcher> m_watcher;
    std::vector<std::string> m_reloadErrors;           ///< problems of the last edit that did not load
    std::vector<std::string> m_restFindings;           ///< bodies of the level file that move with no shot fired
    std::future<std::vector<std::string>> m_restCheck; ///< the rest check running on a worker thread
    std::future<void> m_settling;                      ///< the settle step running on a worker thread (live play)
    /// A load shorter than this shows nothing; a longer one shows its progress.
    static constexpr std::chrono::milliseconds kQuietLoad{300};
    ReloadNotice m_reloadNotice;
};

} // namespace abalike::app
