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

} // namespace

Settings parseSettings(std::string_view text)
{
    const nlohmann::json root = parseSaveJson(text, kSettingsFormat);
    Settings settings;
    // Every key is optional: a file from an older abalike simply lacks the newer ones.
    if (const auto it = root.find("music_volume"); it != root.end())
        settings.musicVolume = readNumber(*it, "/music_volume", 0.0, 1.0);
    if (const auto it = root.find("effects_volume"); it != root.end())
        settings.effectsVolume = readNumber(*it, "/effects_volume", 0.0, 1.0);
    if (const auto it = root.find("show_preview"); it != root.end())
        settings.showPreview = readBool(*it, "/show_preview");
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
    root["show_preview"] = settings.showPreview;
    root["show_actual_path"] = settings.showActualPath;
    root["fullscreen"] = settings.fullscreen;
    root["window"] = {std::clamp<unsigned>(settings.windowWidth, kMinWidth, kMaxWidth),
                      std::clamp<unsigned>(settings.windowHeight, kMinHeight, kMaxHeight)};
    return dumpSaveJson(root);
}

} // namespace abalike
