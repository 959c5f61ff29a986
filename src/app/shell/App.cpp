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
#include <abalike/util/ProcessCopy.hpp>

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
/// A live frame done this early was not paced by vsync (Xvfb, drivers without it): it waits out the rest of a 60 Hz
/// frame instead of spinning, which leaves the CPU to the endless mode's worker. A frame vsync paces takes the whole
/// period and never waits.
constexpr double kUnpacedFrameS = 0.012;
} // namespace

App::App(AppOptions options, Campaign campaign, SaveStore store, std::unique_ptr<sf::Font> font)
    : m_options(std::move(options)), m_font(std::move(font)),
      m_window(m_options.window != nullptr ? *m_options.window : m_ownWindow), m_store(std::move(store)),
      m_notices(m_trace), m_settings(m_options, &*m_store, m_trace, m_notices),
      m_progress(std::move(campaign), m_options, &*m_store, m_settings, m_trace, m_notices),
      m_ui(m_window, m_font.get(), m_settings), m_run(m_options),
      m_context(m_navigator, m_ui, m_settings, m_progress, m_notices, m_trace, m_run), m_script(m_options.script)
{
    // The game's searches (the editor's solver, the endless mode's generator) replay their tries instead of copying
    // the process: after each copy, every page the render threads write (frame buffers, textures) would be copied
    // again at ~14 us a page on a virtual machine, a hitch in every frame while a search runs.
    allowProcessCopies(false);
    // Scripted runs read the player's files (tests point ABALIKE_DATA_DIR at a fixture) but never write them.
    m_notices.takeMessagesOf(*m_store);
    if (!m_options.tracePath.empty() && !m_trace.open(m_options.tracePath))
        std::cerr << "abalike: cannot write the trace to " << escapeForTerminal(m_options.tracePath) << "\n";
    screens().setObserver(
        [this](std::string_view change, std::string_view screen) {
            m_trace.write(std::string(change), {{"screen", std::string(screen)}});
        });
    m_settings.onApplied([this](const Settings& before, const Settings& after) { settingsApplied(before, after); });
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
    const unsigned width = sizeGiven ? *m_options.width : m_settings.current().windowWidth;
    const unsigned height = sizeGiven ? *m_options.height : m_settings.current().windowHeight;
    if (m_settings.current().fullscreen && !sizeGiven)
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
    m_run.input().releaseAll(); // the old window's releases will not arrive
    screens().resize(size);
}

void App::openFirstScreen()
{
    if (!m_options.firstScreen)
        throw std::logic_error("AppOptions::firstScreen is not set (screens/GameScreens.hpp sets the game's)");
    screens().push(m_options.firstScreen(m_context));
    screens().applyPending();
}

int App::run()
{
    openWindow();
    const sf::Clock loadClock;
    openFirstScreen();
    FrameObserver* observer = m_options.observer;
    const int layoutEvery = observer != nullptr ? observer->layoutEvery() : 0;
    sf::Clock clock;
    while (!m_navigator.exitCode())
    {
        const bool lastFrame = runFrame(clock, layoutEvery);
        if (observer != nullptr && m_run.frame() == 1)
            observer->firstFrame(static_cast<double>(loadClock.getElapsedTime().asMicroseconds()) * 1e-6);
        if (screens().empty())
            m_navigator.quit(m_navigator.exitCode().value_or(0));
        if (lastFrame)
            break;
    }
    const int exitCode = finishRun(m_navigator.exitCode().value_or(0), layoutEvery > 0);
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
    m_run.startFrame();
    FrameTimes& times = m_run.frameTimes();
    m_trace.setFrame(m_run.frame());
    for (const sf::Event& event : m_script.eventsForFrame(static_cast<int>(m_run.frame())))
        dispatch(event);
    for (const sf::Event& posted : m_navigator.takePosted())
        dispatch(posted);
    sf::Event event{};
    while (m_window.pollEvent(event))
        dispatch(event);

    const double frameS = offline ? kStepS : std::min(static_cast<double>(clock.restart().asSeconds()), kMaxFrameS);
    for (const sf::Event& repeat : m_gamepad.tick(frameS))
        dispatch(repeat);
    times.updateS += lap();
    const int steps = stepsForFrame(frameS);
    for (int i = 0; i < steps && !m_navigator.exitCode() && screens().top() != nullptr; ++i)
        screens().top()->fixedUpdate(kStepS);
    times.physicsS += lap();
    if (Screen* top = screens().top())
        top->frameUpdate(frameS);
    m_notices.age(frameS);
    times.updateS += lap() - times.previewS;

    const bool lastFrame = offline && m_run.frame() >= *m_options.frames;
    if (layoutEvery > 0)
    {
        if (!lastFrame && m_run.frame() % layoutEvery == 0)
            m_options.observer->laidOut(recordFrame(false));
    }
    else if (!lastFrame)
    {
        drawFrame(true);
        times.drawS += lap();
        m_window.display();
        times.displayS += lap();
    }
    screens().applyPending();
    times.updateS += lap();
    times.totalS = static_cast<double>(frameClock.getElapsedTime().asMicroseconds()) * 1e-6;
    if (m_options.observer != nullptr && !lastFrame)
        m_options.observer->frameTimed(times);
    if (!offline && times.totalS < kUnpacedFrameS)
        sf::sleep(sf::seconds(static_cast<float>(kStepS - times.totalS)));
    return lastFrame;
}

int App::finishRun(int exitCode, bool layoutOnly)
{
    // The last frame as the screens are after its changes: what the player would see next. A laid-out run hands it
    // to the observer; a trace lists its texts (so a scripted run can check what a screen says) and its layout.
    if (layoutOnly)
    {
        screens().finishBackgroundWork();
        m_options.observer->laidOut(recordFrame(false));
    }
    else if (!m_options.screenshotPath.empty() || !m_options.tracePath.empty())
    {
        screens().finishBackgroundWork();
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
    m_trace.write("exit", {{"code", exitCode}, {"screens", screens().names()}});
    return exitCode;
}

int App::stepsForFrame(double frameS)
{
    if (m_options.frames)
    {
        // Exactly 1/60 s of game time per frame, whatever the wall clock says; counted in whole steps so rounding
        // cannot drift.
        const auto target =
            static_cast<long long>(std::floor(static_cast<double>(m_run.frame()) * (1.0 / 60.0) / kStepS + 1e-9));
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
    m_run.input().apply(event);
    if (handleGlobal(event))
        return;
    if (Screen* top = screens().top())
        top->handleEvent(event);
}

bool App::handleGlobal(const sf::Event& event)
{
    switch (event.type)
    {
    case sf::Event::Closed:
        if (Screen* top = screens().top(); top == nullptr || !top->onCloseRequest())
            m_navigator.quit(0);
        return true;
    case sf::Event::Resized:
    {
        const sf::Vector2u size(event.size.width, event.size.height);
        m_window.setView(sf::View(sf::FloatRect(0.0f, 0.0f, static_cast<float>(size.x), static_cast<float>(size.y))));
        screens().resize(size);
        return true;
    }
    case sf::Event::MouseButtonReleased:
        if (Screen* top = screens().top();
            event.mouseButton.button == sf::Mouse::Right && top != nullptr && top->rightClickIsBack())
        {
            // The mouse's way back out of a menu: the same Escape the keyboard and the pad's B press.
            sf::Event back{};
            back.type = sf::Event::KeyPressed;
            back.key.code = sf::Keyboard::Escape;
            m_navigator.post(back);
            back.type = sf::Event::KeyReleased;
            m_navigator.post(back);
            return true;
        }
        return false;
    case sf::Event::KeyPressed:
        if (event.key.code == sf::Keyboard::F1 && !helpOnTop())
        {
            toggleHelp();
            return true;
        }
        return false;
    case sf::Event::TextEntered:
    {
        const Screen* top = screens().top();
        if (event.text.unicode == '?' && (top == nullptr || !top->wantsTextInput()) && !helpOnTop())
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

bool App::helpOnTop() const
{
    const Screen* top = m_navigator.screens().top();
    return top != nullptr && top->name() == kHelpScreenName;
}

void App::toggleHelp()
{
    if (!m_options.helpScreen)
        return;
    const Screen* top = screens().top();
    if (top != nullptr && top->name() == kHelpScreenName)
        return; // the help screen closes itself on F1 and '?', once (a '?' is a key press, its text and a release)
    screens().push(m_options.helpScreen(m_context));
}

void App::drawFrame(bool reuseCovered)
{
    m_window.clear(palette::kSkyBottom);
    if (reuseCovered)
        screens().drawWithSnapshot(m_window);
    else
        screens().draw(m_window);
    m_notices.draw(m_window, m_ui);
}

FrameLayout App::recordFrame(bool pixels)
{
    FrameLayout layout;
    layout.frame = m_run.frame();
    layout.window = m_ui.windowSize();
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

void App::settingsApplied(const Settings& before, const Settings& after)
{
    screens().invalidateSnapshot(); // the screens under the settings show the new look at once
    if (after.fullscreen != before.fullscreen || after.windowWidth != before.windowWidth ||
        after.windowHeight != before.windowHeight)
        reopenWindow();
}

} // namespace abalike::app
