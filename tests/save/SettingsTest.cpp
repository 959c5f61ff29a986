#include <abalike/save/SaveError.hpp>
#include <abalike/save/Settings.hpp>
#include <gtest/gtest.h>
#include <limits>

namespace abalike
{
namespace
{

std::string settingsErrorOf(const std::string& text)
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
    settings.preview = PreviewMode::Short;
    settings.showActualPath = false;
    settings.fullscreen = true;
    settings.windowWidth = 1920;
    settings.windowHeight = 1080;
    EXPECT_EQ(parseSettings(settingsToJson(settings)), settings);
}

TEST(Settings, AccessibilityAndDisplayKeysRoundTrip)
{
    Settings settings;
    settings.mute = true;
    settings.textScale = 1.75;
    settings.palette = Palette::ColourBlindSafe;
    settings.highContrast = true;
    settings.reducedMotion = true;
    settings.teachingOverlay = true;
    settings.openAllLevels = true;
    const std::string text = settingsToJson(settings);
    EXPECT_NE(text.find("\"open_all_levels\": true"), std::string::npos) << text;
    EXPECT_NE(text.find("\"palette\": \"colour_blind_safe\""), std::string::npos) << text;
    EXPECT_EQ(parseSettings(text), settings);
}

TEST(Settings, AFileFromTheFirstReleaseStillReads)
{
    // settings.json as the first release wrote it: none of the newer keys.
    const Settings old = parseSettings(R"({"format": 1, "music_volume": 0.5, "effects_volume": 0.25,
        "show_preview": true, "show_actual_path": false, "fullscreen": false, "window": [1600, 900]})");
    EXPECT_EQ(old.windowWidth, 1600u);
    EXPECT_EQ(old.effectsVolume, 0.25);
    EXPECT_FALSE(old.mute);
    EXPECT_EQ(old.textScale, 1.0);
    EXPECT_EQ(old.palette, Palette::Standard);
    EXPECT_FALSE(old.highContrast);
    EXPECT_FALSE(old.reducedMotion);
    EXPECT_FALSE(old.teachingOverlay);
    EXPECT_FALSE(old.openAllLevels);
    EXPECT_EQ(old.preview, PreviewMode::Full);
    EXPECT_EQ(old.wording, Wording::School);
    // A first-release file that turned the preview off keeps it off.
    EXPECT_EQ(parseSettings(R"({"format": 1, "show_preview": false})").preview, PreviewMode::Off);
    EXPECT_EQ(parseSettings(R"({"format": 1, "preview": "short"})").preview, PreviewMode::Short);
    EXPECT_EQ(parseSettings(R"({"format": 1, "wording": "university"})").wording, Wording::University);
}

TEST(Settings, NewKeysAreCheckedToo)
{
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "text_scale": 3})").find("/text_scale: expected a number from 1"),
              std::string::npos);
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "text_scale": 0.5})").find("/text_scale"), std::string::npos);
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "palette": "neon"})").find("/palette: expected \"standard\" or"),
              std::string::npos);
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "palette": 2})").find("/palette"), std::string::npos);
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "mute": "yes"})").find("/mute: expected true or false"),
              std::string::npos);
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "teaching_overlay": 0})").find("/teaching_overlay"), std::string::npos);
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "preview": "half"})")
                  .find("/preview: expected \"full\", \"short\" or \"off\""),
              std::string::npos);
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "wording": "college"})")
                  .find("/wording: expected \"school\" or \"university\""),
              std::string::npos);
}

TEST(Settings, WritesOnlyWhatItCanReadBack)
{
    Settings settings;
    settings.musicVolume = std::numeric_limits<double>::quiet_NaN();
    settings.effectsVolume = 7.0;
    settings.windowWidth = 1;
    settings.windowHeight = 100000;
    settings.textScale = 9.0;
    const Settings back = parseSettings(settingsToJson(settings));
    EXPECT_EQ(back.textScale, 2.0);
    EXPECT_EQ(back.musicVolume, 0.0);
    EXPECT_EQ(back.effectsVolume, 1.0);
    EXPECT_EQ(back.windowWidth, 320u);
    EXPECT_EQ(back.windowHeight, 4320u);
}

TEST(Settings, ValuesOutOfRangeAreErrors)
{
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "music_volume": 1.5})").find("/music_volume: expected a number from 0"),
              std::string::npos);
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "effects_volume": "loud"})").find("/effects_volume"), std::string::npos);
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "fullscreen": 1})").find("/fullscreen: expected true or false, got 1"),
              std::string::npos);
    EXPECT_NE(
        settingsErrorOf(R"({"format": 1, "window": [100, 100]})").find("/window/0: expected a whole number from 320"),
        std::string::npos);
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "window": [1280]})").find("/window: expected [WIDTH, HEIGHT]"),
              std::string::npos);
}

TEST(Settings, NonFiniteNumbersAreRejected)
{
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "music_volume": NaN})").find("not valid JSON"), std::string::npos);
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "music_volume": -Infinity})").find("not valid JSON"), std::string::npos);
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "music_volume": 1e400})").find("number overflow"), std::string::npos);
    EXPECT_NE(settingsErrorOf(R"({"format": 1, "music_volume": null})").find("/music_volume"), std::string::npos);
}

} // namespace
} // namespace abalike
