#include "input/ScriptedInput.hpp"
#include "input/InputState.hpp"
#include "input/KeyNames.hpp"

#include <gtest/gtest.h>

#include <set>

namespace abalike::app
{
namespace
{

TEST(KeyNames, EveryKeyHasAUniqueNameThatMapsBack)
{
    const std::vector<std::string>& names = allKeyNames();
    EXPECT_EQ(names.size(), static_cast<std::size_t>(sf::Keyboard::KeyCount));
    EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
    for (int k = 0; k < sf::Keyboard::KeyCount; ++k)
    {
        const auto key = static_cast<sf::Keyboard::Key>(k);
        ASSERT_FALSE(keyName(key).empty()) << k;
        EXPECT_EQ(keyFromName(keyName(key)), key) << keyName(key);
    }
    EXPECT_EQ(keyFromName("Escape"), sf::Keyboard::Escape);
    EXPECT_EQ(keyFromName("Add"), sf::Keyboard::Add);
    EXPECT_EQ(keyFromName("F1"), sf::Keyboard::F1);
    EXPECT_FALSE(keyFromName("escape").has_value()) << "names are SFML's, case and all";
    EXPECT_TRUE(keyName(sf::Keyboard::Unknown).empty());
}

TEST(ScriptedInput, AKeyTapIsAPressAndARelease)
{
    ScriptEvent tap;
    tap.key = "Down";
    tap.shift = true;
    const std::vector<sf::Event> events = toWindowEvents(tap);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].type, sf::Event::KeyPressed);
    EXPECT_EQ(events[1].type, sf::Event::KeyReleased);
    EXPECT_EQ(events[0].key.code, sf::Keyboard::Down);
    EXPECT_TRUE(events[0].key.shift);
    EXPECT_FALSE(events[0].key.control);

    // Ctrl comes up after the key, as on a keyboard: what follows does not read Ctrl as held.
    ScriptEvent selectAll;
    selectAll.key = "A";
    selectAll.ctrl = true;
    const std::vector<sf::Event> chord = toWindowEvents(selectAll);
    ASSERT_EQ(chord.size(), 3u);
    EXPECT_TRUE(chord[0].key.control);
    EXPECT_EQ(chord[2].type, sf::Event::KeyReleased);
    EXPECT_EQ(chord[2].key.code, sf::Keyboard::LControl);
    EXPECT_FALSE(chord[2].key.control);
}

TEST(ScriptedInput, HeldKeysAndButtonsStayDownUntilReleased)
{
    InputState state;
    ScriptEvent hold;
    hold.key = "LShift";
    hold.action = ScriptEvent::Action::Press;
    for (const sf::Event& e : toWindowEvents(hold))
        state.apply(e);
    EXPECT_TRUE(state.shift());
    ScriptEvent press;
    press.kind = ScriptEvent::Kind::Mouse;
    press.action = ScriptEvent::Action::Press;
    press.button = "right";
    press.x = 12;
    press.y = 34;
    for (const sf::Event& e : toWindowEvents(press))
        state.apply(e);
    EXPECT_TRUE(state.buttonDown(sf::Mouse::Right));
    EXPECT_FALSE(state.buttonDown(sf::Mouse::Left));
    EXPECT_EQ(state.pointer(), sf::Vector2i(12, 34));

    hold.action = ScriptEvent::Action::Release;
    for (const sf::Event& e : toWindowEvents(hold))
        state.apply(e);
    EXPECT_FALSE(state.shift());
    sf::Event lost{};
    lost.type = sf::Event::LostFocus;
    state.apply(lost);
    EXPECT_FALSE(state.buttonDown(sf::Mouse::Right)) << "releases never arrive after focus is lost";
}

TEST(ScriptedInput, TextIsOneEventPerCharacterAndWheelKeepsItsSign)
{
    ScriptEvent text;
    text.kind = ScriptEvent::Kind::Text;
    text.text = "a\xC3\xA9";
    const std::vector<sf::Event> chars = toWindowEvents(text);
    ASSERT_EQ(chars.size(), 2u);
    EXPECT_EQ(chars[0].text.unicode, U'a');
    EXPECT_EQ(chars[1].text.unicode, U'\u00e9');

    ScriptEvent wheel;
    wheel.kind = ScriptEvent::Kind::Wheel;
    wheel.wheelDelta = -3;
    wheel.x = 5;
    const std::vector<sf::Event> turn = toWindowEvents(wheel);
    ASSERT_EQ(turn.size(), 1u);
    EXPECT_EQ(turn[0].type, sf::Event::MouseWheelScrolled);
    EXPECT_EQ(turn[0].mouseWheelScroll.delta, -3.0f);
    EXPECT_EQ(turn[0].mouseWheelScroll.x, 5);
}

TEST(ScriptedInput, HandsOutEachFramesEventsOnce)
{
    InputScript script;
    for (int frame : {1, 1, 3, 7})
    {
        ScriptEvent e;
        e.frame = frame;
        e.key = "Up";
        script.events.push_back(e);
    }
    ScriptedInput input(script);
    EXPECT_EQ(input.eventsForFrame(1).size(), 4u) << "two taps, each a press and a release";
    EXPECT_TRUE(input.eventsForFrame(2).empty());
    EXPECT_EQ(input.eventsForFrame(3).size(), 2u);
    EXPECT_FALSE(input.finished());
    EXPECT_EQ(input.eventsForFrame(10).size(), 2u) << "a late frame still gets what is due";
    EXPECT_TRUE(input.finished());
    EXPECT_EQ(input.lastFrame(), 7);
}

} // namespace
} // namespace abalike::app
