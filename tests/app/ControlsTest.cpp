#include "input/Controls.hpp"
#include "input/AimController.hpp"
#include "input/Gamepad.hpp"
#include "input/InputState.hpp"
#include "render/PullReach.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

using namespace abalike::app;

namespace
{
sf::Event key(sf::Keyboard::Key code, bool shift = false, bool pressed = true)
{
    sf::Event event{};
    event.type = pressed ? sf::Event::KeyPressed : sf::Event::KeyReleased;
    event.key.code = code;
    event.key.shift = shift;
    return event;
}

sf::Event padButton(unsigned button, bool pressed)
{
    sf::Event event{};
    event.type = pressed ? sf::Event::JoystickButtonPressed : sf::Event::JoystickButtonReleased;
    event.joystickButton.joystickId = 0;
    event.joystickButton.button = button;
    return event;
}

sf::Event padAxis(sf::Joystick::Axis axis, float position)
{
    sf::Event event{};
    event.type = sf::Event::JoystickMoved;
    event.joystickMove.joystickId = 0;
    event.joystickMove.axis = axis;
    event.joystickMove.position = position;
    return event;
}

const Camera& testCamera()
{
    static const Camera camera = Camera::fromView({-12.8f, 7.2f}, 50.0f, {1280u, 720u});
    return camera;
}

bool press(AimController& aim, sf::Keyboard::Key code, bool shift = false, bool alt = false)
{
    sf::Event event = key(code, shift);
    event.key.alt = alt;
    return aim.handleEvent(event, testCamera(), {0.0f, 0.0f});
}
} // namespace

TEST(AimKeys, StepsLandOnTheHalfDegreeAndOnePercentGrid)
{
    AimController aim;
    aim.set(43.2, 0.515);
    press(aim, sf::Keyboard::Up);
    EXPECT_NEAR(aim.angleDeg(), 43.5, 1e-12);
    press(aim, sf::Keyboard::Down);
    press(aim, sf::Keyboard::Down);
    EXPECT_NEAR(aim.angleDeg(), 42.5, 1e-12);
    press(aim, sf::Keyboard::Right);
    EXPECT_NEAR(aim.powerFraction(), 0.52, 1e-12);
    press(aim, sf::Keyboard::Left);
    press(aim, sf::Keyboard::Left);
    EXPECT_NEAR(aim.powerFraction(), 0.50, 1e-12);
}

TEST(AimKeys, AltTakesFineStepsOfATenthOfADegreeAndAFifthOfAPercent)
{
    AimController aim;
    aim.set(43.23, 0.5);
    press(aim, sf::Keyboard::Up, false, true);
    EXPECT_NEAR(aim.angleDeg(), 43.3, 1e-9);
    press(aim, sf::Keyboard::Down, false, true);
    press(aim, sf::Keyboard::Down, false, true);
    EXPECT_NEAR(aim.angleDeg(), 43.1, 1e-9);
    press(aim, sf::Keyboard::Right, false, true);
    EXPECT_NEAR(aim.powerFraction(), 0.502, 1e-9);
}

TEST(AimDrag, TheDragsScreenLengthIsThePullAtAnyZoom)
{
    // 200 px at 720 px of the window's shorter side is a full pull; at half the zoom the same drag is the same pull.
    EXPECT_FLOAT_EQ(fullPullPx({1280u, 720u}), 200.0f);
    EXPECT_FLOAT_EQ(fullPullPx({1920u, 1080u}), 300.0f);
    EXPECT_FLOAT_EQ(fullPullPx({600u, 1000u}), 600.0f * 200.0f / 720.0f); // a tall window: its width counts
    for (const float pixelsPerMetre : {50.0f, 25.0f, 8.0f})
    {
        const Camera camera = Camera::fromView({-12.8f, 7.2f}, pixelsPerMetre, {1280u, 720u});
        const sf::Vector2f pouch{0.0f, 0.0f};
        const sf::Vector2f pouchPx = camera.toScreen(pouch);
        AimController aim;
        sf::Event down{};
        down.type = sf::Event::MouseButtonPressed;
        down.mouseButton = {sf::Mouse::Left, static_cast<int>(pouchPx.x), static_cast<int>(pouchPx.y)};
        aim.handleEvent(down, camera, pouch);
        ASSERT_TRUE(aim.dragging());
        // 100 px back and 100 px down: a 45 degree launch at 141/200 of a full pull.
        sf::Event move{};
        move.type = sf::Event::MouseMoved;
        move.mouseMove = {static_cast<int>(pouchPx.x) - 100, static_cast<int>(pouchPx.y) + 100};
        aim.handleEvent(move, camera, pouch);
        const double dx = pouchPx.x - static_cast<float>(move.mouseMove.x);
        const double dy = static_cast<float>(move.mouseMove.y) - pouchPx.y;
        EXPECT_NEAR(aim.angleDeg(), std::atan2(dy, dx) * 180.0 / M_PI, 1e-4) << pixelsPerMetre;
        EXPECT_NEAR(aim.angleDeg(), 45.0, 0.5) << pixelsPerMetre;
        EXPECT_NEAR(aim.powerFraction(), std::hypot(dx, dy) / 200.0, 1e-6) << pixelsPerMetre;
        // One pixel more is at most 0.5 % of the pull.
        move.mouseMove.x -= 1;
        const double before = aim.powerFraction();
        aim.handleEvent(move, camera, pouch);
        EXPECT_LE(aim.powerFraction() - before, 0.005);
        // Losing focus cancels the pull: back to the aim before it, nothing launches.
        sf::Event lost{};
        lost.type = sf::Event::LostFocus;
        EXPECT_FALSE(aim.handleEvent(lost, camera, pouch));
        EXPECT_FALSE(aim.dragging());
        EXPECT_DOUBLE_EQ(aim.angleDeg(), AimController::kDefaultAngleDeg);
        EXPECT_DOUBLE_EQ(aim.powerFraction(), AimController::kDefaultPower);
    }
}

TEST(AimKeys, ShiftTakesCoarseStepsOfFiveDegreesAndTenPercent)
{
    AimController aim; // 45 degrees, 50 %
    press(aim, sf::Keyboard::Up, true);
    EXPECT_NEAR(aim.angleDeg(), 50.0, 1e-12);
    aim.set(43.2, 0.47);
    press(aim, sf::Keyboard::Up, true);
    EXPECT_NEAR(aim.angleDeg(), 45.0, 1e-12); // to the grid first, not 48.2
    press(aim, sf::Keyboard::Down, true);
    EXPECT_NEAR(aim.angleDeg(), 40.0, 1e-12);
    press(aim, sf::Keyboard::Right, true);
    EXPECT_NEAR(aim.powerFraction(), 0.5, 1e-12);
    press(aim, sf::Keyboard::Right, true);
    EXPECT_NEAR(aim.powerFraction(), 0.6, 1e-12);
}

TEST(AimKeys, StepsStopAtTheLimits)
{
    AimController aim;
    aim.set(88.0, 0.97);
    press(aim, sf::Keyboard::Up, true);
    press(aim, sf::Keyboard::Right, true);
    EXPECT_DOUBLE_EQ(aim.angleDeg(), 90.0);
    EXPECT_DOUBLE_EQ(aim.powerFraction(), 1.0);
    aim.set(-88.0, 0.05);
    press(aim, sf::Keyboard::Down, true);
    press(aim, sf::Keyboard::Left, true);
    EXPECT_DOUBLE_EQ(aim.angleDeg(), -90.0);
    EXPECT_NEAR(aim.powerFraction(), 0.01, 1e-12); // never below one step: a zero pull launches nothing
}

TEST(AimKeys, SpaceAndEnterLaunchButOnlyWithEnoughPull)
{
    AimController aim;
    EXPECT_TRUE(press(aim, sf::Keyboard::Space));
    EXPECT_TRUE(press(aim, sf::Keyboard::Enter));
    EXPECT_FALSE(press(aim, sf::Keyboard::Up));
    aim.set(45.0, 0.1); // a 0.2 m pull is under the 0.25 m minimum
    EXPECT_FALSE(press(aim, sf::Keyboard::Space));
}

TEST(InputStateRepeat, AHeldKeyIsARepeatAndANewPressIsNot)
{
    InputState input;
    input.apply(key(sf::Keyboard::Space));
    EXPECT_FALSE(input.lastPressRepeated());
    input.apply(key(sf::Keyboard::Space)); // the system's key repeat: no release in between
    EXPECT_TRUE(input.lastPressRepeated());
    input.apply(key(sf::Keyboard::Space, false, false));
    input.apply(key(sf::Keyboard::Space));
    EXPECT_FALSE(input.lastPressRepeated());
}

TEST(GamepadMapping, ButtonsPressTheirKeys)
{
    GamepadTranslator pad;
    const std::vector<std::pair<unsigned, sf::Keyboard::Key>> expected{
        {0, sf::Keyboard::Space}, {1, sf::Keyboard::Escape}, {2, sf::Keyboard::R},     {3, sf::Keyboard::T},
        {5, sf::Keyboard::Home},  {6, sf::Keyboard::F1},     {7, sf::Keyboard::Escape}};
    for (const auto& [button, code] : expected)
    {
        const std::vector<sf::Event> down = pad.translate(padButton(button, true));
        ASSERT_EQ(down.size(), 1u) << "button " << button;
        EXPECT_EQ(down[0].type, sf::Event::KeyPressed);
        EXPECT_EQ(down[0].key.code, code) << "button " << button;
        const std::vector<sf::Event> up = pad.translate(padButton(button, false));
        ASSERT_EQ(up.size(), 1u);
        EXPECT_EQ(up[0].type, sf::Event::KeyReleased);
    }
    EXPECT_TRUE(pad.translate(padButton(12, true)).empty()); // a button with no use
}

TEST(GamepadMapping, StickAndDpadAreArrowsWithHysteresis)
{
    GamepadTranslator pad;
    EXPECT_TRUE(pad.translate(padAxis(sf::Joystick::Y, -40.0f)).empty()); // under the press threshold
    std::vector<sf::Event> out = pad.translate(padAxis(sf::Joystick::Y, -80.0f));
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].type, sf::Event::KeyPressed);
    EXPECT_EQ(out[0].key.code, sf::Keyboard::Up);
    EXPECT_TRUE(pad.translate(padAxis(sf::Joystick::Y, -40.0f)).empty()); // still held above the release threshold
    out = pad.translate(padAxis(sf::Joystick::Y, -20.0f));
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].type, sf::Event::KeyReleased);
    EXPECT_EQ(out[0].key.code, sf::Keyboard::Up);

    out = pad.translate(padAxis(sf::Joystick::PovX, 100.0f));
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].key.code, sf::Keyboard::Right);
    // Straight across to the other side: release one arrow, press the other.
    out = pad.translate(padAxis(sf::Joystick::PovX, -100.0f));
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[0].type, sf::Event::KeyReleased);
    EXPECT_EQ(out[0].key.code, sf::Keyboard::Right);
    EXPECT_EQ(out[1].type, sf::Event::KeyPressed);
    EXPECT_EQ(out[1].key.code, sf::Keyboard::Left);

    out = pad.translate(padAxis(sf::Joystick::V, -90.0f));
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].key.code, sf::Keyboard::Add);                        // right stick up zooms in
    EXPECT_TRUE(pad.translate(padAxis(sf::Joystick::Z, 100.0f)).empty()); // triggers are not used
}

TEST(GamepadMapping, AHeldDirectionRepeatsLikeAHeldKey)
{
    GamepadTranslator pad;
    pad.translate(padAxis(sf::Joystick::X, 90.0f));
    EXPECT_TRUE(pad.tick(0.30).empty());         // before the repeat delay
    std::vector<sf::Event> out = pad.tick(0.06); // 0.36 s: the first repeat
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].type, sf::Event::KeyPressed);
    EXPECT_EQ(out[0].key.code, sf::Keyboard::Right);
    EXPECT_EQ(pad.tick(0.16).size(), 2u); // 0.52 s: two more at 0.43 and 0.51
    pad.translate(padAxis(sf::Joystick::X, 0.0f));
    EXPECT_TRUE(pad.tick(1.0).empty());
}

TEST(GamepadMapping, LbHeldMakesArrowsCoarseAndUnplugReleasesEverything)
{
    GamepadTranslator pad;
    std::vector<sf::Event> out = pad.translate(padButton(4, true));
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].key.code, sf::Keyboard::LShift);
    out = pad.translate(padAxis(sf::Joystick::Y, 100.0f));
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].key.code, sf::Keyboard::Down);
    EXPECT_TRUE(out[0].key.shift);

    sf::Event unplug{};
    unplug.type = sf::Event::JoystickDisconnected;
    out = pad.translate(unplug);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[0].type, sf::Event::KeyReleased);
    EXPECT_EQ(out[0].key.code, sf::Keyboard::Down);
    EXPECT_EQ(out[1].type, sf::Event::KeyReleased);
    EXPECT_EQ(out[1].key.code, sf::Keyboard::LShift);
    EXPECT_TRUE(pad.tick(1.0).empty());
}

TEST(ControlsTable, EveryPlayActionHasAKeyAndAMouseWay)
{
    for (const ControlBinding& row : controlTable())
    {
        EXPECT_FALSE(row.action.empty());
        EXPECT_FALSE(row.mouse.empty()) << row.action;
        EXPECT_FALSE(row.keys.empty()) << row.action;
    }
}

TEST(ControlsTable, ThePlayersGuidePrintsExactlyThisTable)
{
    std::ifstream file(std::string(ABALIKE_SOURCE_DIR) + "/docs/playing.md");
    ASSERT_TRUE(file) << "docs/playing.md not found";
    std::stringstream text;
    text << file.rdbuf();
    const std::string readme = text.str();
    const std::string begin = "<!-- controls table: generated from src/app/input/Controls.cpp -->\n";
    const std::string end = "<!-- end of controls table -->";
    const std::size_t from = readme.find(begin);
    const std::size_t to = readme.find(end);
    ASSERT_NE(from, std::string::npos) << "docs/playing.md has no controls table marker";
    ASSERT_NE(to, std::string::npos);
    EXPECT_EQ(readme.substr(from + begin.size(), to - from - begin.size()), controlTableMarkdown())
        << "Paste this between the markers in docs/playing.md:\n"
        << controlTableMarkdown();
}
