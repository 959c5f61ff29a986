#include "save/SaveJson.hpp"

#include <abalike/save/SaveError.hpp>
#include <abalike/save/Settings.hpp>
#include <algorithm>

namespace abalike
{

namespace
{

constexpr int kSettingsFormat = 1;
/// The window sizes `abalike play --size` accepts.
constexpr int kMinWidth = 320;
constexpr int kMinHeight = 240;
constexpr int kMaxWidth = 7680;
constexpr int kMaxHeight = 4320;

constexpr double kMinTextScale = 1.0;
constexpr double kMaxTextScale = 2.0;

PreviewMode readPreview(const nlohmann::json& value, const std::string& pointer)
{
    const std::string& name = readString(value, pointer);
    if (name == "full")
        return PreviewMode::Full;
    if (name == "short")
        return PreviewMode::Short;
    if (name == "off")
        return PreviewMode::Off;
    throw SaveFormatError(pointer + ": expected \"full\", \"short\" or \"off\"");
}

} // namespace

const char* previewModeName(PreviewMode mode)
{
    return mode == PreviewMode::Short ? "short" : mode == PreviewMode::Off ? "off" : "full";
}

const char* playModeName(PlayMode mode)
{
    return mode == PlayMode::Learn ? "learn" : "game";
}

std::optional<PlayMode> parsePlayMode(std::string_view name)
{
    if (name == "game")
        return PlayMode::Game;
    if (name == "learn")
        return PlayMode::Learn;
    return std::nullopt;
}

const char* wordingName(Wording wording)
{
    return wording == Wording::University ? "university" : "school";
}

std::optional<Wording> parseWording(std::string_view name)
{
    if (name == "school")
        return Wording::School;
    if (name == "university")
        return Wording::University;
    return std::nullopt;
}

const char* paletteName(Palette palette)
{
    return palette == Palette::ColourBlindSafe ? "colour_blind_safe" : "standard";
}

Settings parseSettings(std::string_view text)
{
    const nlohmann::json root = parseSaveJson(text, kSettingsFormat);
    Settings settings;
    // Every key is optional: a file from an older abalike simply lacks the newer ones.
    if (const auto it = root.find("music_volume"); it != root.end())
        settings.musicVolume = readNumber(*it, "/music_volume", 0.0, 1.0);
    if (const auto it = root.find("effects_volume"); it != root.end())
        settings.effectsVolume = readNumber(*it, "/effects_volume", 0.0, 1.0);
    // "show_preview" (true or false) is what earlier versions wrote; "preview" names the three choices.
    if (const auto it = root.find("show_preview"); it != root.end())
        settings.preview = readBool(*it, "/show_preview") ? PreviewMode::Full : PreviewMode::Off;
    if (const auto it = root.find("preview"); it != root.end())
        settings.preview = readPreview(*it, "/preview");
    if (const auto it = root.find("game_preview"); it != root.end())
        settings.gamePreview = readPreview(*it, "/game_preview");
    if (const auto it = root.find("mode"); it != root.end())
    {
        const std::optional<PlayMode> mode = parsePlayMode(readString(*it, "/mode"));
        if (!mode)
            throw SaveFormatError("/mode: expected \"game\" or \"learn\"");
        settings.mode = *mode;
    }
    if (const auto it = root.find("show_actual_path"); it != root.end())
        settings.showActualPath = readBool(*it, "/show_actual_path");
    if (const auto it = root.find("fullscreen"); it != root.end())
        settings.fullscreen = readBool(*it, "/fullscreen");
    if (const auto it = root.find("window"); it != root.end())
    {
        if (!it->is_array() || it->size() != 2)
            throw SaveFormatError("/window: expected [WIDTH, HEIGHT] in pixels");
        settings.windowWidth = static_cast<unsigned>(readInt((*it)[0], "/window/0", kMinWidth, kMaxWidth));
        settings.windowHeight = static_cast<unsigned>(readInt((*it)[1], "/window/1", kMinHeight, kMaxHeight));
    }
    if (const auto it = root.find("mute"); it != root.end())
        settings.mute = readBool(*it, "/mute");
    if (const auto it = root.find("text_scale"); it != root.end())
        settings.textScale = readNumber(*it, "/text_scale", kMinTextScale, kMaxTextScale);
    if (const auto it = root.find("palette"); it != root.end())
    {
        const std::string& name = readString(*it, "/palette");
        if (name == paletteName(Palette::Standard))
            settings.palette = Palette::Standard;
        else if (name == paletteName(Palette::ColourBlindSafe))
            settings.palette = Palette::ColourBlindSafe;
        else
            throw SaveFormatError("/palette: expected \"standard\" or \"colour_blind_safe\"");
    }
    if (const auto it = root.find("high_contrast"); it != root.end())
        settings.highContrast = readBool(*it, "/high_contrast");
    if (const auto it = root.find("reduced_motion"); it != root.end())
        settings.reducedMotion = readBool(*it, "/reduced_motion");
    if (const auto it = root.find("teaching_overlay"); it != root.end())
        settings.teachingOverlay = readBool(*it, "/teaching_overlay");
    if (const auto it = root.find("open_all_levels"); it != root.end())
        settings.openAllLevels = readBool(*it, "/open_all_levels");
    if (const auto it = root.find("wording"); it != root.end())
    {
        const std::optional<Wording> wording = parseWording(readString(*it, "/wording"));
        if (!wording)
            throw SaveFormatError("/wording: expected \"school\" or \"university\"");
        settings.wording = *wording;
    }
    return settings;
}

std::string settingsToJson(const Settings& settings)
{
    // Clamped on the way out too, so whatever the game holds is written as a file parseSettings accepts.
    const auto volume = [](double v)
    {
        return v >= 0.0 && v <= 1.0 ? v : v > 1.0 ? 1.0 : 0.0;
    };
    nlohmann::ordered_json root;
    root["format"] = kSettingsFormat;
    root["music_volume"] = volume(settings.musicVolume);
    root["effects_volume"] = volume(settings.effectsVolume);
    root["mode"] = playModeName(settings.mode);
    root["preview"] = previewModeName(settings.preview);
    root["game_preview"] = previewModeName(settings.gamePreview);
    root["show_actual_path"] = settings.showActualPath;
    root["fullscreen"] = settings.fullscreen;
    root["window"] = {std::clamp<unsigned>(settings.windowWidth, kMinWidth, kMaxWidth),
                      std::clamp<unsigned>(settings.windowHeight, kMinHeight, kMaxHeight)};
    root["mute"] = settings.mute;
    root["text_scale"] = settings.textScale >= kMinTextScale && settings.textScale <= kMaxTextScale
                             ? settings.textScale
                             : (settings.textScale > kMaxTextScale ? kMaxTextScale : kMinTextScale);
    root["palette"] = paletteName(settings.palette);
    root["high_contrast"] = settings.highContrast;
    root["reduced_motion"] = settings.reducedMotion;
    root["teaching_overlay"] = settings.teachingOverlay;
    root["open_all_levels"] = settings.openAllLevels;
    root["wording"] = wordingName(settings.wording);
    return dumpSaveJson(root);
}

} // namespace abalike
