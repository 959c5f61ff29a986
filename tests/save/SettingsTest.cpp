#include <abalike/save/SaveError.hpp>
#include <abalike/save/Settings.hpp>
#include <gtest/gtest.h>
#include <limits>

namespace abalike
{
namespace
{

std::string errorOf(const std::string& text)
{
    try
    {
        parseSettings(text);
    }
    catch (const SaveFormatError& e)
    {
        return e.what();
    }
    return "";
}

TEST(Settings, MissingKeysKeepTheirDefaults)
{
    EXPECT_EQ(parseSettings(R"({"format": 1})"), Settings{});
    Settings expected;
    expected.fullscreen = true;
    EXPECT_EQ(parseSettings(R"({"format": 1, "fullscreen": true})"), expected);
}

TEST(Settings, UnknownKeysFromANewerGameAreIgnored)
{
    EXPECT_EQ(parseSettings(R"({"format": 1, "colour_blind_palette": true})"), Settings{});
}

TEST(Settings, JsonRoundTrips)
{
    Settings settings;
    settings.musicVolume = 0.125;
    settings.effectsVolume = 0.0;
    settings.showPreview = false;
    settings.showActualPath = false;
    settings.fullscreen = true;
    settings.windowWidth = 1920;
    settings.windowHeight = 1080;
    EXPECT_EQ(parseSettings(settingsToJson(settings)), settings);
}

TEST(Settings, WritesOnlyWhatItCanReadBack)
{
    Settings settings;
    settings.musicVolume = std::numeric_limits<double>::quiet_NaN();
    settings.effectsVolume = 7.0;
    settings.windowWidth = 1;
    settings.windowHeight = 100000;
    const Settings back = parseSettings(settingsToJson(settings));
    EXPECT_EQ(back.musicVolume, 0.0);
    EXPECT_EQ(back.effectsVolume, 1.0);
    EXPECT_EQ(back.windowWidth, 320u);
    EXPECT_EQ(back.windowHeight, 4320u);
}

TEST(Settings, ValuesOutOfRangeAreErrors)
{
    EXPECT_NE(errorOf(R"({"format": 1, "music_volume": 1.5})").find("/music_volume: expected a number from 0"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"format": 1, "effects_volume": "loud"})").find("/effects_volume"), std::string::npos);
    EXPECT_NE(errorOf(R"({"format": 1, "fullscreen": 1})").find("/fullscreen: expected true or false, got 1"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"format": 1, "window": [100, 100]})").find("/window/0: expected a whole number from 320"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"format": 1, "window": [1280]})").find("/window: expected [WIDTH, HEIGHT]"),
              std::string::npos);
}

TEST(Settings, NonFiniteNumbersAreRejected)
{
    EXPECT_NE(errorOf(R"({"format": 1, "music_volume": NaN})").find("not valid JSON"), std::string::npos);
    EXPECT_NE(errorOf(R"({"format": 1, "music_volume": -Infinity})").find("not valid JSON"), std::string::npos);
    EXPECT_NE(errorOf(R"({"format": 1, "music_volume": 1e400})").find("number overflow"), std::string::npos);
    EXPECT_NE(errorOf(R"({"format": 1, "music_volume": null})").find("/music_volume"), std::string::npos);
}

} // namespace
} // namespace abalike
