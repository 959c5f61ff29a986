#include "screens/PlayScreen.hpp"

#include "render/Font.hpp"
#include "render/Screenshot.hpp"

#include <abalike/level/SafeText.hpp>
#include <abalike/save/DataDirectory.hpp>

#include <SFML/System/Clock.hpp>
#include <SFML/Window/Event.hpp>
#include <abalike/level/LevelIO.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <utility>

namespace abalike::app
{

namespace
{
constexpr double kOfflineFrameS = 1.0 / 60.0;
constexpr double kMaxFrameS = 0.25; // a slow frame cannot start a spiral of death
constexpr float kLastShotFade = 0.45f;

sf::Vector2f toVector(const std::array<double, 2>& p)
{
    return {static_cast<float>(p[0]), static_cast<float>(p[1])};
}
} // namespace

PlayScreen::PlayScreen(sf::RenderWindow& window, const PlayOptions& options, std::vector<LevelDef> levels,
                       const sf::Font* font)
    : m_window(window), m_options(options), m_levels(std::move(levels)),
      m_camera(Camera::fitLevel(m_levels.front(), Catalog::builtin(), window.getSize())), m_script(options.shots),
      m_overlay(font), m_hud(font), m_results(font), m_reloadNotice(font)
{
    startLevel(0);
    if (!options.frames && options.shots.empty())
    {
        m_store.emplace(defaultDataDirectory());
        m_store->load();
        for (const std::string& message : m_store->takeMessages())
        {
            std::cerr << "abalike: " << message << '\n';
            m_reloadErrors.push_back(message);
        }
    }
}

void PlayScreen::startLevel(std::size_t index)
{
    m_levelIndex = index;
    m_session = std::make_unique<GameSession>(m_levels[index], Catalog::builtin());
    m_camera = Camera::fitLevel(m_session->level(), m_session->catalog(), m_window.getSize());
    resetAim();
    m_watcher.emplace(m_options.levelPaths.at(index), Catalog::builtin());
    m_reloadErrors.clear();
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
    m_levels[m_levelIndex] = std::move(*reload->level);
    startLevel(m_levelIndex);
}

void PlayScreen::restartLevel()
{
    m_session->restart();
    resetAim();
}

void PlayScreen::saveResultIfFinished()
{
    if (!m_store || m_resultSaved || !m_session->finished())
        return;
    m_resultSaved = true;
    Progress progress = m_store->progress();
    const bool improved = progress.record(m_session->level().id, m_session->score().total(), m_session->stars());
    std::vector<std::string> ids;
    for (const LevelDef& level : m_levels)
        ids.push_back(level.id);
    if (unlockCampaign(progress, ids) || improved)
        m_store->saveProgress(std::move(progress));
    for (const std::string& message : m_store->takeMessages())
    {
        // A folder that cannot be written only means no saving: say so and keep playing.
        std::cerr << "abalike: " << message << '\n';
        m_reloadErrors.push_back(message);
    }
}

void PlayScreen::resetAim()
{
    m_resultSaved = false;
    ++m_generation;
    m_aim.reset();
    m_requestedLaunch.reset();
    m_abilityRequested = false;
    m_scriptAbilityAtS.reset();
    m_preview.reset();
}

int PlayScreen::run()
{
    const bool offline = m_options.frames.has_value();
    if (!offline)
        m_window.setVerticalSyncEnabled(true); // offline frames run as fast as they can (and Xvfb has no vsync)
    const double dt = m_session->world().dt();
    sf::Clock clock;
    double accumulator = 0.0;
    long long frame = 0;
    long long offlineSteps = 0;

    while (!(offline && frame >= *m_options.frames))
    {
        if (!handleEvents())
            break;
        pollLevelFile();
        saveResultIfFinished();
        if (!m_session->notice().empty())
        {
            // The session reset itself (a body escaped to NaN): tell the player in the same panel as file errors.
            std::cerr << "abalike: " << m_session->notice() << '\n';
            m_reloadErrors = {m_session->notice()};
            m_session->clearNotice();
        }
        int steps = 0;
        if (offline)
        {
            // Exactly 1/60 s of game time per frame, whatever the wall clock says; counted in whole steps so
            // rounding cannot drift.
            const auto target =
                static_cast<long long>(std::floor(static_cast<double>(frame + 1) * kOfflineFrameS / dt + 1e-9));
            steps = static_cast<int>(target - offlineSteps);
            offlineSteps = target;
        }
        else
        {
            accumulator += std::min(static_cast<double>(clock.restart().asSeconds()), kMaxFrameS);
            while (accumulator >= dt)
            {
                accumulator -= dt;
                ++steps;
            }
        }
        for (int i = 0; i < steps; ++i)
        {
            if (const std::optional<int> exitCode = fixedStep())
                return *exitCode;
        }
        ++frame;
        render();
        if (offline && frame >= *m_options.frames)
            break; // the last frame stays in the back buffer for the screenshot
        m_window.display();
    }

    int exitCode = 0;
    if (!m_options.screenshotPath.empty())
    {
        render();
        if (!saveScreenshot(m_window, m_options.screenshotPath))
            exitCode = 2;
    }
    m_window.close();
    return exitCode;
}

bool PlayScreen::handleEvents()
{
    sf::Event event{};
    while (m_window.pollEvent(event))
    {
        if (event.type == sf::Event::Closed)
            return false;
        if (event.type == sf::Event::Resized)
        {
            m_window.setView(sf::View(sf::FloatRect(0.0f, 0.0f, static_cast<float>(event.size.width),
                                                    static_cast<float>(event.size.height))));
            m_camera = Camera::fitLevel(m_session->level(), m_session->catalog(), m_window.getSize());
            continue;
        }
        if (event.type == sf::Event::KeyPressed)
        {
            if (event.key.code == sf::Keyboard::Escape)
                return false;
            handleKey(event.key.code);
        }
        const bool click = event.type == sf::Event::MouseButtonPressed && event.mouseButton.button == sf::Mouse::Left;
        const bool space = event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::Space;
        if ((click || space) && m_session->canActivateAbility() && !m_scriptAbilityAtS)
            m_abilityRequested = true;
        if (!playerMayAim())
            continue;
        if (m_aim.handleEvent(event, m_camera, toVector(m_session->launchPoint())))
            m_requestedLaunch = ScriptedShot(m_aim.angleDeg(), aimSpeedMps());
    }
    return true;
}

void PlayScreen::handleKey(sf::Keyboard::Key key)
{
    if (key == sf::Keyboard::R)
        restartLevel();
    const bool next = key == sf::Keyboard::N || key == sf::Keyboard::Enter;
    if (next && m_session->phase() == Phase::Won && m_levelIndex + 1 < m_levels.size())
        startLevel(m_levelIndex + 1);
}

bool PlayScreen::playerMayAim() const
{
    return m_session->phase() == Phase::Aiming && m_session->currentBird() != nullptr &&
           m_script.pending() == nullptr && !m_requestedLaunch;
}

std::optional<int> PlayScreen::fixedStep()
{
    if (m_requestedLaunch)
    {
        const ScriptedShot shot = *m_requestedLaunch;
        m_requestedLaunch.reset();
        try
        {
            m_session->launch(shot.angleDeg, shot.speedMps);
        }
        catch (const LaunchError& error)
        {
            std::cerr << "abalike: " << error.what() << "\n";
        }
    }
    if (m_abilityRequested)
    {
        m_abilityRequested = false;
        m_session->activateAbility();
    }
    // A scripted ability fires at the first step boundary at or after its time, as in `abalike simulate`.
    if (m_scriptAbilityAtS && m_session->phase() == Phase::Flying &&
        m_session->timeSinceLaunch() >= *m_scriptAbilityAtS - 1e-9)
    {
        m_session->activateAbility();
        m_scriptAbilityAtS.reset();
    }
    if (m_session->phase() == Phase::Aiming && m_script.pending() != nullptr)
    {
        if (const std::optional<int> exitCode = fireScriptedShot())
            return exitCode;
    }
    m_session->step();
    return std::nullopt;
}

std::optional<int> PlayScreen::fireScriptedShot()
{
    syncScriptedAim();
    if (!m_script.tick(m_session->world().dt()))
        return std::nullopt;
    const ScriptedShot shot = *m_script.pending();
    m_script.advance();
    ++m_scriptShotNumber;
    try
    {
        const BirdType* bird = m_session->currentBird();
        if (shot.abilityAtS && bird != nullptr && bird->ability == "none")
            throw LaunchError("bird " + std::to_string(m_session->birdsUsed() + 1) + " (" + bird->name +
                              ") has no ability to use");
        m_session->launch(shot.angleDeg, shot.speedMps);
    }
    catch (const LaunchError& error)
    {
        std::cerr << "abalike: shot " << m_scriptShotNumber << ": " << error.what() << "\n";
        return 2;
    }
    m_scriptAbilityAtS = shot.abilityAtS;
    return std::nullopt;
}

void PlayScreen::syncScriptedAim()
{
    const ScriptedShot* shot = m_script.pending();
    if (shot == nullptr || m_session->phase() != Phase::Aiming || m_session->currentBird() == nullptr)
        return;
    const double maxSpeed = m_session->maxLaunchSpeed();
    m_aim.set(shot->angleDeg, maxSpeed > 0.0 ? shot->speedMps / maxSpeed : 0.0);
}

double PlayScreen::aimSpeedMps() const
{
    if (const ScriptedShot* shot = m_script.pending())
        return shot->speedMps;
    const double forceN = m_aim.powerFraction() * m_session->level().slingshot.maxForceN;
    return std::min(m_session->launchSpeedForForce(forceN), m_session->maxLaunchSpeed());
}

std::optional<AimReadout> PlayScreen::aimReadout() const
{
    const BirdType* bird = m_session->currentBird();
    if (m_session->phase() != Phase::Aiming || bird == nullptr)
        return std::nullopt;
    AimReadout readout;
    readout.angleDeg = m_aim.angleDeg();
    readout.speedMps = aimSpeedMps();
    readout.forceN = m_script.pending() != nullptr ? m_session->forceForLaunchSpeed(readout.speedMps)
                                                   : m_aim.powerFraction() * m_session->level().slingshot.maxForceN;
    readout.massKg = bird->massKg;
    readout.releaseTimeS = m_session->catalog().slingshotReleaseTimeS();
    return readout;
}

void PlayScreen::refreshPreview()
{
    if (m_session->phase() != Phase::Aiming || m_session->currentBird() == nullptr)
    {
        m_preview.reset();
        return;
    }
    const PreviewKey key{m_aim.angleDeg(), aimSpeedMps(), m_session->birdsUsed(), m_generation};
    if (m_preview && key == m_previewKey)
        return;
    m_previewKey = key;
    try
    {
        m_preview = m_session->preview(key.angleDeg, key.speedMps);
    }
    catch (const std::exception&)
    {
        // A preview the core cannot compute is not worth stopping the game for.
        m_preview.reset();
    }
}

void PlayScreen::render()
{
    syncScriptedAim();
    refreshPreview();
    const GameSession& session = *m_session;
    m_world.drawBackground(m_window, m_camera, session);

    // While the next bird is aimed, the last shot stays as a faded reference.
    const ShotRecord* lastShot = session.shots().empty() ? nullptr : &session.shots().back();
    const float opacity = session.phase() == Phase::Aiming ? kLastShotFade : 1.0f;
    if (lastShot != nullptr)
        m_overlay.drawShotPaths(m_window, m_camera, *lastShot, opacity);
    m_world.drawForeground(m_window, m_camera, session, m_aim.pullOffset());
    if (lastShot != nullptr)
        m_overlay.drawShotMarkers(m_window, m_camera, *lastShot, opacity);
    if (m_preview)
        m_overlay.drawPreview(m_window, m_camera, *m_preview);

    m_hud.draw(m_window, m_window.getSize(), session, aimReadout());
    if (session.finished())
        m_results.draw(m_window, m_window.getSize(), session, m_levelIndex + 1 < m_levels.size());
    m_reloadNotice.draw(m_window, m_window.getSize(), m_reloadErrors);
}

int runPlay(const PlayOptions& options)
{
    if (options.levelPaths.empty())
    {
        std::cerr << "abalike: no level to play\n";
        return 2;
    }
    std::vector<LevelDef> levels;
    for (const std::string& path : options.levelPaths)
    {
        try
        {
            levels.push_back(loadLevel(path, Catalog::builtin()));
        }
        catch (const LevelLoadError& error)
        {
            for (const LevelIssue& issue : error.issues())
                std::cerr << issue.format() << "\n";
            if (error.issues().empty())
                std::cerr << escapeForTerminal(path) << ": error: " << error.what() << "\n";
            return 2;
        }
        catch (const std::exception& error)
        {
            std::cerr << escapeForTerminal(path) << ": error: " << escapeForTerminal(error.what()) << "\n";
            return 2;
        }
    }

#if defined(__unix__) && !defined(__APPLE__)
    // SFML aborts the process when it cannot reach an X server; say why instead.
    if (std::getenv("DISPLAY") == nullptr)
    {
        std::cerr << "abalike: no display (DISPLAY is not set); for offline frames run under xvfb-run\n";
        return 2;
    }
#endif
    const std::unique_ptr<sf::Font> font = loadGameFont();
    sf::RenderWindow window(sf::VideoMode(options.width, options.height), "Angry Birds Alike",
                            sf::Style::Titlebar | sf::Style::Close | sf::Style::Resize);
    try
    {
        PlayScreen screen(window, options, std::move(levels), font.get());
        return screen.run();
    }
    catch (const std::exception& error)
    {
        std::cerr << "abalike: " << error.what() << "\n";
        return 2;
    }
}

} // namespace abalike::app
