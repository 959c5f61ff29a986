#include "shell/App.hpp"

#include "endless/EndlessGame.hpp"
#include "shell/DataPaths.hpp"

#include "render/Hud.hpp"
#include "render/Label.hpp"
#include "render/Palette.hpp"
#include "render/ScreenRegions.hpp"
#include "render/Screenshot.hpp"

#include <abalike/level/SafeText.hpp>
#include <abalike/save/DataDirectory.hpp>

#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/OpenGL.hpp>
#include <SFML/System/Clock.hpp>
#include <SFML/System/Sleep.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <utility>

namespace abalike::app
{

namespace
{
constexpr double kMaxFrameS = 0.25; // a slow frame cannot start a spiral of death
constexpr double kNoticeS = 6.0;
/// A live frame done this early was not paced by vsync (Xvfb, drivers without it): it waits out the rest of a 60 Hz
/// frame instead of spinning, which leaves the CPU to the endless mode's worker. A frame vsync paces takes the whole
/// period and never waits.
constexpr double kUnpacedFrameS = 0.012;
constexpr std::size_t kMaxNotices = 4;
} // namespace

App::App(AppOptions options, Campaign campaign, SaveStore store, std::unique_ptr<sf::Font> font)
    : m_options(std::move(options)), m_campaign(std::move(campaign)), m_font(std::move(font)),
      m_window(m_options.window != nullptr ? *m_options.window : m_ownWindow), m_script(m_options.script),
      m_store(std::move(store))
{
    // Scripted runs read the player's files (tests point ABALIKE_DATA_DIR at a fixture) but never write them.
    m_settings = m_store->settings();
    setActiveLook(lookFor(m_settings.palette, m_settings.highContrast));
    m_progress = m_store->progress();
    if (unlockCampaign(m_progress, m_campaign.levelIds()) && !scripted())
        m_store->saveProgress(m_progress);
    takeStoreMessages();
    if (!m_options.tracePath.empty() && !m_trace.open(m_options.tracePath))
        std::cerr << "abalike: cannot write the trace to " << escapeForTerminal(m_options.tracePath) << "\n";
    m_screens.setObserver(
        [this](std::string_view change, std::string_view screen) {
            m_trace.write(std::string(change), {{"screen", std::string(screen)}});
        });
}

App::~App() = default;

void App::openWindow()
{
    if (m_options.window != nullptr)
    {
        // A lent window: as it is, with the view of its whole size.
        m_window.setView(m_window.getDefaultView());
        return;
    }
    // --size wins over the saved size, and a size asked for on the command line is a window, not full screen.
    const bool sizeGiven = m_options.width.has_value();
    const unsigned width = sizeGiven ? *m_options.width : m_settings.windowWidth;
    const unsigned height = sizeGiven ? *m_options.height : m_settings.windowHeight;
    if (m_settings.fullscreen && !sizeGiven)
        m_window.create(sf::VideoMode::getDesktopMode(), "Angry Birds Alike", sf::Style::Fullscreen);
    else
    {
        m_window.create(sf::VideoMode(width, height), "Angry Birds Alike",
                        sf::Style::Titlebar | sf::Style::Close | sf::Style::Resize);
        // Centred on the screen: a bare X server (no window manager) puts a new window wherever SFML asks, which is
        // not always on the screen.
        const sf::VideoMode desktop = sf::VideoMode::getDesktopMode();
        m_window.setPosition({(static_cast<int>(desktop.width) - static_cast<int>(width)) / 2,
                              (static_cast<int>(desktop.height) - static_cast<int>(height)) / 2});
    }
    m_window.setKeyRepeatEnabled(true);
    // Offline frames run as fast as they can (and Xvfb has no vsync).
    m_window.setVerticalSyncEnabled(!m_options.frames.has_value());
}

void App::reopenWindow()
{
    // A --size on the command line wins over the saved size and full screen: nothing to change then.
    if (!m_window.isOpen() || m_options.width.has_value() || m_options.window != nullptr)
        return;
    openWindow();
    const sf::Vector2u size = m_window.getSize();
    m_window.setView(sf::View(sf::FloatRect(0.0f, 0.0f, static_cast<float>(size.x), static_cast<float>(size.y))));
    m_input.releaseAll(); // the old window's releases will not arrive
    m_screens.resize(size);
}

void App::openFirstScreen()
{
    if (!m_options.firstScreen)
        throw std::logic_error("AppOptions::firstScreen is not set (screens/GameScreens.hpp sets the game's)");
    m_screens.push(m_options.firstScreen(*this));
    m_screens.applyPending();
}

int App::run()
{
    openWindow();
    const sf::Clock loadClock;
    openFirstScreen();
    FrameObserver* observer = m_options.observer;
    const int layoutEvery = observer != nullptr ? observer->layoutEvery() : 0;
    sf::Clock clock;
    while (!m_exitCode)
    {
        const bool lastFrame = runFrame(clock, layoutEvery);
        if (observer != nullptr && m_frame == 1)
            observer->firstFrame(static_cast<double>(loadClock.getElapsedTime().asMicroseconds()) * 1e-6);
        if (m_screens.empty())
            quit(m_exitCode.value_or(0));
        if (lastFrame)
            break;
    }
    const int exitCode = finishRun(m_exitCode.value_or(0), layoutEvery > 0);
    if (m_options.window == nullptr)
        m_window.close();
    return exitCode;
}

bool App::runFrame(sf::Clock& clock, int layoutEvery)
{
    // The frame's parts are timed for `bench frames`: each lap is the time since the last.
    sf::Clock frameClock;
    sf::Clock partClock;
    const auto lap = [&partClock]
    {
        return static_cast<double>(partClock.restart().asMicroseconds()) * 1e-6;
    };
    const bool offline = m_options.frames.has_value();
    m_frameTimes = FrameTimes{};
    ++m_frame;
    m_trace.setFrame(m_frame);
    for (const sf::Event& event : m_script.eventsForFrame(static_cast<int>(m_frame)))
        dispatch(event);
    for (const sf::Event& posted : std::exchange(m_posted, {}))
        dispatch(posted);
    sf::Event event{};
    while (m_window.pollEvent(event))
        dispatch(event);

    const double frameS = offline ? kStepS : std::min(static_cast<double>(clock.restart().asSeconds()), kMaxFrameS);
    for (const sf::Event& repeat : m_gamepad.tick(frameS))
        dispatch(repeat);
    m_frameTimes.updateS += lap();
    const int steps = stepsForFrame(frameS);
    for (int i = 0; i < steps && !m_exitCode && m_screens.top() != nullptr; ++i)
        m_screens.top()->fixedUpdate(kStepS);
    m_frameTimes.physicsS += lap();
    if (Screen* top = m_screens.top())
        top->frameUpdate(frameS);
    for (Notice& notice : m_notices)
        notice.shownS += frameS;
    std::erase_if(m_notices, [](const Notice& n) { return n.shownS > kNoticeS; });
    m_frameTimes.updateS += lap() - m_frameTimes.previewS;

    const bool lastFrame = offline && m_frame >= *m_options.frames;
    if (layoutEvery > 0)
    {
        if (!lastFrame && m_frame % layoutEvery == 0)
            m_options.observer->laidOut(recordFrame(false));
    }
    else if (!lastFrame)
    {
        drawFrame(true);
        m_frameTimes.drawS += lap();
        m_window.display();
        m_frameTimes.displayS += lap();
    }
    m_screens.applyPending();
    m_frameTimes.updateS += lap();
    m_frameTimes.totalS = static_cast<double>(frameClock.getElapsedTime().asMicroseconds()) * 1e-6;
    if (m_options.observer != nullptr && !lastFrame)
        m_options.observer->frameTimed(m_frameTimes);
    if (!offline && m_frameTimes.totalS < kUnpacedFrameS)
        sf::sleep(sf::seconds(static_cast<float>(kStepS - m_frameTimes.totalS)));
    return lastFrame;
}

int App::finishRun(int exitCode, bool layoutOnly)
{
    // The last frame as the screens are after its changes: what the player would see next. A laid-out run hands it
    // to the observer; a trace lists its texts (so a scripted run can check what a screen says) and its layout.
    if (layoutOnly)
    {
        m_screens.finishBackgroundWork();
        m_options.observer->laidOut(recordFrame(false));
    }
    else if (!m_options.screenshotPath.empty() || !m_options.tracePath.empty())
    {
        m_screens.finishBackgroundWork();
        const FrameLayout layout = recordFrame(true);
        std::vector<std::string> texts;
        std::vector<std::string> kinds;
        for (const DrawnText& text : layout.texts)
        {
            texts.push_back(text.text);
            kinds.emplace_back(textKindName(text.kind));
        }
        m_trace.write("texts", {{"shown", texts}, {"kinds", kinds}});
        const auto rectangles = [](const std::vector<ScreenRegion>& list)
        {
            nlohmann::json out = nlohmann::json::array();
            for (const ScreenRegion& region : list)
                out.push_back({{"name", region.name},
                               {"x", region.rect.left},
                               {"y", region.rect.top},
                               {"w", region.rect.width},
                               {"h", region.rect.height}});
            return out;
        };
        m_trace.write("panels", {{"drawn", rectangles(layout.panels)},
                                 {"keep_visible", rectangles(layout.keepVisible)},
                                 {"window", {layout.window.x, layout.window.y}}});
        if (!m_options.screenshotPath.empty() && !saveScreenshot(m_window, m_options.screenshotPath))
            exitCode = exitCode == 0 ? 2 : exitCode;
    }
    m_trace.write("exit", {{"code", exitCode}, {"screens", m_screens.names()}});
    return exitCode;
}

int App::stepsForFrame(double frameS)
{
    if (m_options.frames)
    {
        // Exactly 1/60 s of game time per frame, whatever the wall clock says; counted in whole steps so rounding
        // cannot drift.
        const auto target =
            static_cast<long long>(std::floor(static_cast<double>(m_frame) * (1.0 / 60.0) / kStepS + 1e-9));
        const auto steps = static_cast<int>(target - m_offlineSteps);
        m_offlineSteps = target;
        return steps;
    }
    m_accumulator += frameS;
    int steps = 0;
    while (m_accumulator >= kStepS)
    {
        m_accumulator -= kStepS;
        ++steps;
    }
    return steps;
}

void App::dispatch(const sf::Event& event)
{
    const bool gamepad = event.type == sf::Event::JoystickButtonPressed ||
                         event.type == sf::Event::JoystickButtonReleased || event.type == sf::Event::JoystickMoved ||
                         event.type == sf::Event::JoystickDisconnected;
    if (gamepad || event.type == sf::Event::LostFocus)
    {
        // A pad speaks through the keys it stands for, so every screen understands it.
        for (const sf::Event& key : gamepad ? m_gamepad.translate(event) : m_gamepad.reset())
            dispatch(key);
        if (gamepad)
            return;
    }
    m_input.apply(event);
    if (handleGlobal(event))
        return;
    if (Screen* top = m_screens.top())
        top->handleEvent(event);
}

bool App::handleGlobal(const sf::Event& event)
{
    switch (event.type)
    {
    case sf::Event::Closed:
        if (Screen* top = m_screens.top(); top == nullptr || !top->onCloseRequest())
            quit(0);
        return true;
    case sf::Event::Resized:
    {
        const sf::Vector2u size(event.size.width, event.size.height);
        m_window.setView(sf::View(sf::FloatRect(0.0f, 0.0f, static_cast<float>(size.x), static_cast<float>(size.y))));
        m_screens.resize(size);
        return true;
    }
    case sf::Event::MouseButtonReleased:
        if (Screen* top = m_screens.top();
            event.mouseButton.button == sf::Mouse::Right && top != nullptr && top->rightClickIsBack())
        {
            // The mouse's way back out of a menu: the same Escape the keyboard and the pad's B press.
            sf::Event back{};
            back.type = sf::Event::KeyPressed;
            back.key.code = sf::Keyboard::Escape;
            post(back);
            back.type = sf::Event::KeyReleased;
            post(back);
            return true;
        }
        return false;
    case sf::Event::KeyPressed:
        if (event.key.code == sf::Keyboard::F1)
        {
            toggleHelp();
            return true;
        }
        return false;
    case sf::Event::TextEntered:
    {
        const Screen* top = m_screens.top();
        if (event.text.unicode == '?' && (top == nullptr || !top->wantsTextInput()))
        {
            toggleHelp();
            return true;
        }
        return false;
    }
    default:
        return false;
    }
}

void App::toggleHelp()
{
    if (!m_options.helpScreen)
        return;
    const Screen* top = m_screens.top();
    if (top != nullptr && top->name() == kHelpScreenName)
        m_screens.pop();
    else
        m_screens.push(m_options.helpScreen(*this));
}

void App::drawFrame(bool reuseCovered)
{
    m_window.clear(palette::kSkyBottom);
    if (reuseCovered)
        m_screens.drawWithSnapshot(m_window);
    else
        m_screens.draw(m_window);
    drawNotices();
}

FrameLayout App::recordFrame(bool pixels)
{
    FrameLayout layout;
    layout.frame = m_frame;
    layout.window = windowSize();
    setScreenRegionSink(&layout.panels);
    setKeepVisibleSink(&layout.keepVisible);
    setDrawnTextSink(&layout.texts);
    if (pixels)
        drawFrame();
    else
    {
        // Every screen draws as in a shown frame, so each panel finds its place; labels and meshes skip their draw
        // calls (drawingPixels) and whatever else is drawn meets an empty scissor box: the rasterizer fills nothing.
        (void)m_window.setActive(true);
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, 0, 0);
        setDrawingPixels(false);
        drawFrame();
        setDrawingPixels(true);
        glDisable(GL_SCISSOR_TEST);
    }
    setScreenRegionSink(nullptr);
    setKeepVisibleSink(nullptr);
    setDrawnTextSink(nullptr);
    return layout;
}

void App::drawNotices()
{
    if (m_font == nullptr || m_notices.empty())
        return;
    const unsigned size = textSize(17.0f);
    const float pad = 8.0f * uiScale();
    const float lineHeight = m_font->getLineSpacing(size);
    const float centre = 0.5f * static_cast<float>(windowSize().x);
    // Each notice wrapped to the window (a long file name must not run off its edges), stacked upwards from above
    // the level's hint.
    const float maxWidth = std::max(100.0f, static_cast<float>(windowSize().x) - 4.0f * pad);
    std::vector<std::vector<std::string>> wrapped;
    std::size_t lines = 0;
    for (const Notice& notice : m_notices)
    {
        wrapped.push_back(wrapText(*m_font, notice.text, size, maxWidth - 2.0f * pad));
        lines += wrapped.back().size();
    }
    float y = static_cast<float>(windowSize().y) - 70.0f * uiScale() - lineHeight * static_cast<float>(lines) -
              pad * static_cast<float>(m_notices.size() - 1);
    for (const std::vector<std::string>& notice : wrapped)
    {
        float width = 0.0f;
        for (const std::string& line : notice)
            width = std::max(width, measureText(*m_font, utf8(line), size).x);
        width += 2.0f * pad;
        const float height = lineHeight * static_cast<float>(notice.size()) + pad;
        sf::RectangleShape box({width, height});
        box.setPosition(centre - 0.5f * width, y - 0.5f * pad);
        recordScreenRegion("notice", {box.getPosition(), box.getSize()});
        box.setFillColor(palette::kPanel);
        m_window.draw(box);
        for (const std::string& line : notice)
        {
            drawLabel(m_window, *m_font, utf8(line), {centre, y}, size, palette::kText, Align::Centre);
            y += lineHeight;
        }
        y += pad;
    }
}

void App::updateSettings(const Settings& settings)
{
    const Settings before = m_settings;
    m_settings = settings;
    m_screens.invalidateSnapshot(); // the screens under the settings show the new look at once
    setActiveLook(lookFor(settings.palette, settings.highContrast));
    if (settings.fullscreen != before.fullscreen || settings.windowWidth != before.windowWidth ||
        settings.windowHeight != before.windowHeight)
        reopenWindow();
    m_trace.write("settings", nlohmann::json::parse(settingsToJson(settings)));
    if (!scripted() && m_store)
        m_store->saveSettings(settings);
    takeStoreMessages();
}

void App::setMode(PlayMode mode)
{
    m_mode = mode;
    if (m_settings.mode != mode)
    {
        Settings settings = m_settings;
        settings.mode = mode;
        updateSettings(settings);
    }
}

void App::recordResult(const std::string& levelId, int score, int stars)
{
    const bool improved = m_progress.record(levelId, score, stars);
    const bool unlocked = unlockCampaign(m_progress, m_campaign.levelIds());
    m_trace.write("result", {{"level", levelId}, {"score", score}, {"stars", stars}});
    if ((improved || unlocked) && !scripted() && m_store)
        m_store->saveProgress(m_progress);
    takeStoreMessages();
}

EndlessGame& App::endless()
{
    if (!m_endless)
    {
        // Seeds from the clock, so that every session generates castles of its own; --seed makes a run repeatable.
        const auto clock = static_cast<std::uint64_t>(std::chrono::system_clock::now().time_since_epoch().count());
        const std::uint64_t seed = m_options.endlessSeed.value_or(1000 + clock % 90000);
        m_endless = std::make_unique<EndlessGame>(std::filesystem::path(levelsDirectory()),
                                                  defaultCacheDirectory() / "generated", seed, m_progress.endless.runs,
                                                  scripted());
    }
    return *m_endless;
}

void App::recordEndless(int levelsWon, int score, bool ended)
{
    bool changed = m_progress.endless.offer(levelsWon, score);
    if (ended)
    {
        ++m_progress.endless.runs;
        changed = true;
    }
    m_trace.write("endless-record", {{"levels_won", levelsWon},
                                     {"score", score},
                                     {"ended", ended},
                                     {"best_score", m_progress.endless.bestScore},
                                     {"longest_run", m_progress.endless.longestRun}});
    if (changed && !scripted() && m_store)
        m_store->saveProgress(m_progress);
    takeStoreMessages();
}

bool App::isUnlocked(const std::string& levelId) const
{
    // A teacher may open every level for a class; progress is kept as it is.
    return m_settings.openAllLevels || m_progress.isUnlocked(levelId);
}

std::vector<ScriptedShot> App::takeScriptedShots()
{
    if (m_shotsTaken)
        return {};
    m_shotsTaken = true;
    return m_options.shots;
}

void App::notify(const std::string& message)
{
    notify(message, "");
}

void App::notify(const std::string& message, const std::string& topic)
{
    std::cerr << "abalike: " << message << '\n';
    m_trace.write("notice", {{"text", message}});
    if (!topic.empty())
        std::erase_if(m_notices, [&topic](const Notice& notice) { return notice.topic == topic; });
    m_notices.push_back({message, 0.0, topic});
    if (m_notices.size() > kMaxNotices)
        m_notices.erase(m_notices.begin());
}

void App::quit(int exitCode)
{
    if (!m_exitCode)
        m_exitCode = exitCode;
}

float App::uiScale() const
{
    return hudScale(m_window.getSize()) * static_cast<float>(m_settings.textScale);
}

unsigned App::textSize(float nominal) const
{
    return static_cast<unsigned>(std::max(9.0f, std::round(nominal * uiScale())));
}

void App::takeStoreMessages()
{
    if (!m_store)
        return;
    for (const std::string& message : m_store->takeMessages())
        notify(message);
}

} // namespace abalike::app
