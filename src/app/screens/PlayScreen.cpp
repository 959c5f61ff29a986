#include "screens/PlayScreen.hpp"

#include "layers/PlayLayerTable.hpp"
#include "play/PlayDrawing.hpp"
#include "play/PlayToolbar.hpp"
#include "render/CameraFocus.hpp"
#include "render/TextFormat.hpp"
#include "screens/EndlessNavigation.hpp"
#include "screens/PauseScreen.hpp"
#include "screens/ResultsScreen.hpp"
#include "shell/AppContext.hpp"
#include "shell/Navigator.hpp"
#include "shell/Notices.hpp"
#include "shell/PlayerProgress.hpp"
#include "shell/PlayerSettings.hpp"
#include "shell/RunControl.hpp"
#include "shell/SessionJson.hpp"
#include "shell/Trace.hpp"
#include "shell/UiMetrics.hpp"
#include "ui/ProgressCard.hpp"

#include <abalike/level/LevelIO.hpp>
#include <abalike/world/RestFindings.hpp>
#include <abalike/world/WorldDigest.hpp>
#include <algorithm>
#include <chrono>
#include <exception>
#include <iostream>
#include <string>
#include <utility>

namespace abalike::app
{

namespace
{
/// How long a scripted shot's preview shows in the slingshot before it fires (game time; the world waits).
constexpr double kScriptedHoldS = 0.5;

sf::Vector2f toVector(const Vec2& p)
{
    return {static_cast<float>(p.x), static_cast<float>(p.y)};
}
} // namespace

PlayScreen::PlayScreen(AppContext& app, PlaySource source)
    : PlayField(app, makePlayLayers(app)), m_source(std::move(source)),
      m_script(app.run().takeScriptedShots(), kScriptedHoldS), m_reloadNotice(app.ui().font())
{
    // On top of the shared layers: the toolbar sees clicks first, so a click on a button neither aims nor fires an
    // ability. (The editor's play mode has its own panels instead.)
    addLayer(std::make_unique<PlayToolbar>());
    findRestProblems();
    startSession(true);
    if (!m_source.path.empty())
        m_watcher.emplace(m_source.path, Catalog::builtin());
}

PlayScreen::~PlayScreen() = default;

void PlayScreen::startSession(bool withOpening)
{
    startLevel(std::make_unique<GameSession>(m_source.level, Catalog::builtin()));
    m_rig.reset(cameraFocus(), m_app.ui().windowSize());
    // A level wider than the aiming view opens with a pan over it to the slingshot (restarts do not).
    if (withOpening && m_rig.startOpening(cameraFocus()))
        m_app.trace().write("camera-opening", {{"seconds", CameraRig::kOpeningS}});
    m_finishHandled = false;
    m_destroyedTraced = 0;
    resetShot();
    m_reloadErrors.clear();
    nlohmann::json event{{"id", m_source.level.id}, {"title", m_source.level.title}};
    if (m_source.campaignIndex)
    {
        event["campaign_index"] = *m_source.campaignIndex;
        event["number"] = levelLabel();
    }
    m_app.trace().write("level", event);
    levelStarted();
    startSettling();
}

void PlayScreen::startSettling()
{
    // A scripted run settles in its first physics step as it always has, so its frames are the same on every run.
    if (m_app.run().scripted())
        return;
    // The settle step is the world's first step; on a worker thread, so that a large level (seconds for the
    // 1 000-block wall) shows its progress instead of a window that does not answer. Until it ends, nothing else
    // touches the session: no input, no update, no drawing of the world.
    GameSession* session = m_session.get();
    m_settling = std::async(std::launch::async, [session] { session->step(); });
    // Most levels settle in milliseconds: wait that long with nothing shown; a longer load shows the progress card.
    m_settling.wait_for(kQuietLoad);
    finishSettling(false);
}

void PlayScreen::finishSettling(bool wait)
{
    if (!m_settling.valid())
        return;
    if (!wait && m_settling.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
        return;
    m_settling.get(); // what the step threw, if anything, is thrown here
}

void PlayScreen::restartLevel()
{
    m_session->restart();
    m_rig.reset(cameraFocus(), m_app.ui().windowSize());
    m_finishHandled = false;
    m_destroyedTraced = 0;
    resetShot();
    m_app.trace().write("restart", {{"id", m_source.level.id}});
    levelStarted();
    startSettling();
}

std::optional<std::size_t> PlayScreen::nextLevelIndex() const
{
    if (!m_source.campaignIndex || *m_source.campaignIndex + 1 >= m_app.progress().campaign().levels.size())
        return std::nullopt;
    return *m_source.campaignIndex + 1;
}

std::string PlayScreen::levelLabel() const
{
    // A generated level's title says it all: its kind and the seed that replays it ("Castle 4711").
    if (m_source.endless || (!m_source.campaignIndex && m_source.level.id.starts_with("generated-")))
        return "";
    return m_source.campaignIndex ? m_app.progress().campaign().levels[*m_source.campaignIndex].number
                                  : m_source.level.id;
}

PlayMode PlayScreen::playMode() const
{
    return m_source.mode.value_or(m_app.settings().mode());
}

void PlayScreen::goToNextLevel()
{
    if (m_source.endless)
    {
        if (m_session->finished())
            playNextEndlessLevel(m_app);
        return;
    }
    const std::optional<std::size_t> next = nextLevelIndex();
    if (!next || m_session->phase() != Phase::Won)
        return;
    const CampaignLevel& level = m_app.progress().campaign().levels[*next];
    m_app.navigator().screens().replace(
        std::make_unique<PlayScreen>(m_app, PlaySource{level.level, level.path, next, m_source.mode}));
}

void PlayScreen::resetShot()
{
    resetAim();
    m_aimedBird = kNoBirdAimed;
    m_script.dropAbility();
}

void PlayScreen::findRestProblems()
{
    // A level file that does not stand plays, with what is wrong in the banner. Once per version of the file, not
    // per restart, and on a worker thread: the check simulates 10 s of the level (a large scene's takes seconds)
    // and the level starts without waiting for it. Its own world, its own copy of the level: nothing is shared.
    collectRestProblems(true); // a check of an older version may still run: let it end (its result is dropped)
    m_restFindings.clear();
    if (m_source.path.empty())
        return;
    m_restCheck =
        std::async(std::launch::async,
                   [level = m_source.level, path = m_source.path]
                   {
                       std::vector<std::string> findings;
                       for (const LevelIssue& issue : restIssues(level, Catalog::builtin(), checkRest(level), path))
                           findings.push_back(issue.format());
                       return findings;
                   });
    // The banner moves the ground up (cameraFocus): known before the camera is placed, it never slides in over the
    // slingshot. A scripted run waits for it, so that its frames are the same on every run; live play as long as a
    // quiet load (most levels check in milliseconds), else it comes when ready.
    if (m_app.run().scripted())
        collectRestProblems(true);
    else if (m_restCheck.wait_for(kQuietLoad) == std::future_status::ready)
        collectRestProblems(false);
}

void PlayScreen::collectRestProblems(bool wait)
{
    if (!m_restCheck.valid())
        return;
    if (!wait && m_restCheck.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
        return;
    m_restFindings = m_restCheck.get();
}

void PlayScreen::finishBackgroundWork()
{
    finishSettling(true);
    collectRestProblems(true);
}

void PlayScreen::pollLevelFile()
{
    std::optional<LevelWatcher::Reload> reload = m_watcher ? m_watcher->poll() : std::nullopt;
    if (!reload)
        return;
    if (!reload->level)
    {
        m_reloadErrors.clear();
        for (const LevelIssue& issue : reload->issues)
        {
            m_reloadErrors.push_back(issue.format());
            std::cerr << issue.format() << "\n";
        }
        return;
    }
    m_source.level = std::move(*reload->level);
    findRestProblems();
    startSession(false); // a designer's save reloads in place, without the opening pan
}

void PlayScreen::handleEvent(const sf::Event& event)
{
    // F is followed even while the level settles: a key held from the start counts.
    if (m_fastForward.handleEvent(event) || settling())
        return;
    // Any key, button or wheel ends the opening pan, and still does what it does.
    if (event.type == sf::Event::KeyPressed || event.type == sf::Event::MouseButtonPressed ||
        event.type == sf::Event::MouseWheelScrolled)
        m_rig.skipOpening();
    if (offerToLayers(event))
        return;
    // The problems banner: B or a click on it opens or folds it.
    if (event.type == sf::Event::MouseButtonPressed && event.mouseButton.button == sf::Mouse::Left &&
        m_reloadNotice.handleClick(static_cast<float>(event.mouseButton.x), static_cast<float>(event.mouseButton.y)))
        return;
    if (event.type == sf::Event::KeyPressed)
        handleKey(event.key);

    // The ability takes a new press: a Space held since the launch repeats, and must not fire it by accident.
    const bool click = event.type == sf::Event::MouseButtonPressed && event.mouseButton.button == sf::Mouse::Left;
    const bool key = event.type == sf::Event::KeyPressed &&
                     (event.key.code == sf::Keyboard::Space || event.key.code == sf::Keyboard::Enter) &&
                     !m_app.run().input().lastPressRepeated();
    const bool ability = (click || key) && m_session->canActivateAbility() && !m_script.abilityPending();
    if (ability)
        requestAbility();

    // A left press that neither fires an ability nor takes hold of the bird pans the camera (empty sky).
    const bool mayAim = playerMayAim();
    const sf::Vector2f pouch = toVector(m_session->launchPoint());
    bool leftIsFree = !ability;
    if (const BirdType* bird = m_session->currentBird())
        m_aim.setBird(m_world.loadedBirdAt(*m_session, m_aim.pullOffset()), static_cast<float>(bird->radiusM));
    if (click && mayAim)
        leftIsFree = !m_aim.grabs({static_cast<float>(event.mouseButton.x), static_cast<float>(event.mouseButton.y)},
                                  m_rig.camera(), pouch);
    if (click && mayAim && !leftIsFree)
        m_rig.holdStill(); // a press on the bird grabs it, and the view stops moving under the hand
    if (!m_aim.dragging() && m_cameraControls.handleEvent(event, m_rig, leftIsFree))
        return;
    if (!mayAim)
        return;
    if (m_aim.handleEvent(event, m_rig.camera(), pouch))
        requestLaunch();
}

void PlayScreen::handleKey(const sf::Event::KeyEvent& key)
{
    switch (key.code)
    {
    case sf::Keyboard::Escape:
    case sf::Keyboard::P:
        m_app.navigator().screens().push(std::make_unique<PauseScreen>(m_app, *this));
        break;
    case sf::Keyboard::R:
        restartLevel();
        break;
    case sf::Keyboard::N:
        goToNextLevel();
        break;
    case sf::Keyboard::B:
        if (!m_reloadErrors.empty() || !m_restFindings.empty())
            m_reloadNotice.toggle();
        break;
    default:
        break;
    }
}

bool PlayScreen::playerMayAim() const
{
    return m_session->phase() == Phase::Aiming && !m_session->winPending() && m_session->currentBird() != nullptr &&
           m_script.pending() == nullptr && !launchPending();
}

void PlayScreen::fixedUpdate(double dtS)
{
    (void)dtS; // the session steps at its own fixed rate, which is the app's
    if (settling())
        return;
    if (frozen() || !slowMotion().takeStep())
        return;
    physicsStep();
    // Holding F: more steps of the free flight in this tick, never past the first contact.
    for (int extra = 1; extra < m_fastForward.stepsPerTick(slowMotion().divisor()) &&
                        m_session->phase() == Phase::Flying && m_session->world().birdInFreeFlight();
         ++extra)
        physicsStep();
}

void PlayScreen::stepOnce()
{
    physicsStep();
}

void PlayScreen::physicsStep()
{
    applyRequests();
    if (!advanceScript())
        return;
    // The genre's way: each new bird sits at rest in the pouch and is pulled afresh (learn mode keeps the last aim,
    // so that one change can be tried at a time).
    if (playMode() == PlayMode::Game && m_session->phase() == Phase::Aiming && !m_aim.dragging() &&
        m_aimedBird != m_session->birdsUsed())
    {
        m_aim.rest();
        m_aimedBird = m_session->birdsUsed();
    }
    traceDefeats();
    afterStep();
    finishIfDone();
}

void PlayScreen::traceDefeats()
{
    const std::vector<DestroyedEvent>& destroyed = m_session->destroyed();
    if (destroyed.size() < m_destroyedTraced) // the session reset itself
        m_destroyedTraced = 0;
    for (std::size_t i = m_destroyedTraced; i < destroyed.size(); ++i)
        if (destroyed[i].kind == EntityKind::Block || destroyed[i].kind == EntityKind::Pig)
            m_app.trace().write("defeat", nlohmann::json(defeatJson(destroyed[i])));
    m_destroyedTraced = destroyed.size();
}

bool PlayScreen::advanceScript()
{
    syncScriptedAim();
    ShotSequence::Tick tick = ShotSequence::Tick::Idle;
    try
    {
        tick = m_script.advance(*m_session, m_session->world().dt());
    }
    catch (const LaunchError& error)
    {
        std::cerr << "abalike: " << error.what() << "\n";
        m_app.navigator().quit(2);
        return false;
    }
    if (const std::optional<std::size_t> fired = m_script.firedNumber())
    {
        const ScriptedShot& shot = m_script.shot(*fired);
        m_app.trace().write("launch", {{"angle_deg", shot.angleDeg}, {"speed", shot.speedMps}, {"scripted", true}});
    }
    if (tick == ShotSequence::Tick::Idle)
        m_session->step(); // no script, or none of it left: the world moves on while the player aims
    return tick != ShotSequence::Tick::Held;
}

void PlayScreen::finishIfDone()
{
    if (m_finishHandled || !m_session->finished())
        return;
    m_finishHandled = true;
    const GameSession& session = *m_session;
    m_app.trace().write("finished", {{"level", session.level().id},
                                     {"won", session.phase() == Phase::Won},
                                     {"reason", session.endReason()},
                                     {"score", session.score().total()},
                                     {"stars", session.stars()},
                                     {"sim_time_s", session.simTime()},
                                     {"bodies_digest", bodiesDigest(session.world())}});
    // Only campaign levels count towards progress; a scene from a file or the editor is not the player's record.
    if (m_source.campaignIndex)
        m_app.progress().recordResult(m_app.progress().campaign().levels[*m_source.campaignIndex].key,
                                      session.score().total(), session.stars());
    if (m_source.endless)
    {
        EndlessGame& endless = m_app.progress().endless();
        if (session.phase() == Phase::Won)
        {
            endless.won(session.score().total());
            m_app.progress().recordEndless(endless.run().levelsWon(), endless.run().score(), false);
        }
        else
        {
            const EndlessRun::Result run = endless.lost();
            m_app.progress().recordEndless(run.levelsWon, run.score, true);
        }
    }
    m_app.navigator().screens().push(std::make_unique<ResultsScreen>(m_app, *this));
}

void PlayScreen::syncScriptedAim()
{
    const ScriptedShot* shot = m_script.pending();
    if (shot == nullptr || m_session->phase() != Phase::Aiming || m_session->currentBird() == nullptr)
        return;
    m_aim.set(shot->angleDeg, m_session->band()->forSpeed(shot->speedMps).fraction);
}

std::optional<double> PlayScreen::scriptedSpeedMps() const
{
    if (const ScriptedShot* shot = m_script.pending())
        return shot->speedMps;
    return std::nullopt;
}

void PlayScreen::frameUpdate(double frameS)
{
    finishSettling(false);
    if (settling())
        return;
    pollLevelFile();
    syncScriptedAim();
    refreshPreview();
    collectRestProblems(false);
    m_rig.update(cameraFocus(), frameS);
    updateLayers(frameS);
}

const std::vector<std::string>& PlayScreen::bannerLines() const
{
    return m_reloadErrors.empty() ? m_restFindings : m_reloadErrors;
}

const char* PlayScreen::bannerHeading() const
{
    return m_reloadErrors.empty() ? ReloadNotice::kDoesNotStand : ReloadNotice::kEditDidNotLoad;
}

CameraFocus PlayScreen::cameraFocus() const
{
    CameraFocus focus = cameraFocusOf(*m_session);
    // The teaching overlay's panels reach down about 40 % of the window: keep the flight below them.
    if (m_app.settings().current().teachingOverlay)
        focus.topReserved = kTeachingTopReserved;
    // At large text the keys and the hint at the bottom reach above the ground line's usual place: the ground goes
    // above them, so that they cover neither the slingshot nor the birds waiting by it.
    const sf::Vector2u size = m_app.ui().windowSize();
    if (size.y > 0)
    {
        const auto textScale = static_cast<float>(m_app.settings().current().textScale);
        // The problems banner (folded, one line) sits above the keys: the ground goes above it too, so that it never
        // covers the bird queue or the feet of the level's bodies.
        // (The slingshot's foot reaches a little below the ground line: the banner keeps a wider gap.)
        const float scale = hudScale(size);
        const float banner = m_reloadNotice.reach(size, bannerLines(), textScale, bannerHeading());
        const float text = std::max(m_hud.bottomTextHeight(size, m_session->level(), textScale) + 4.0f * scale,
                                    banner > 0.0f ? banner + 12.0f * scale : 0.0f);
        const float lifted = text / static_cast<float>(size.y);
        focus.groundFromBottom = std::clamp(lifted, camera_limits::kGroundFromBottom, kMostGroundFromBottom);
    }
    return focus;
}

void PlayScreen::onResize(sf::Vector2u size)
{
    m_rig.resize(size);
}

void PlayScreen::draw(sf::RenderTarget& target)
{
    if (settling())
    {
        drawSettleProgress(target);
        return;
    }
    drawField(target);
    m_reloadNotice.draw(target, target.getSize(), bannerLines(),
                        static_cast<float>(m_app.settings().current().textScale), bannerHeading());
}

void PlayScreen::drawSettleProgress(sf::RenderTarget& target) const
{
    const GameWorld& world = m_session->world();
    const int planned = std::max(1, world.settleSubstepsPlanned());
    const int done = std::min(world.settleSubstepsDone(), planned);
    const std::size_t bodies = m_source.level.blocks.size() + m_source.level.pigs.size();
    Progress progress;
    progress.title = "Loading " + m_source.level.title;
    progress.detail = "Settling " + formatPoints(static_cast<int>(bodies)) + " bodies (part " +
                      std::to_string(std::min(done + 1, planned)) + " of " + std::to_string(planned) +
                      ") so that they stand from the first frame";
    progress.fraction = static_cast<float>(done) / static_cast<float>(planned);
    drawProgressCard(target, m_app.ui().font(), progress, m_app.ui().textSize(22.0f), m_app.ui().textSize(15.0f),
                     m_app.ui().scale());
}

} // namespace abalike::app
