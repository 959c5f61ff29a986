#pragma once

#include <string>
#include <string_view>

namespace abalike
{

/// The player's preferences. Every field has a default, and a settings file may leave any of them out.
struct Settings
{
    double musicVolume = 0.7;   ///< 0 to 1
    double effectsVolume = 1.0; ///< 0 to 1
    bool showPreview = true;    ///< draw the RK4 preview dots while aiming
    bool showActualPath = true; ///< trace the path the bird really flew
    bool fullscreen = false;
    unsigned windowWidth = 1280; ///< 320 to 7680 pixels
    unsigned windowHeight = 720; ///< 240 to 4320 pixels

    bool operator==(const Settings&) const = default;
};

/// Parses the text of settings.json. Throws SaveFormatError saying what is wrong and where.
Settings parseSettings(std::string_view text);

/// The text of settings.json.
std::string settingsToJson(const Settings& settings);

} // namespace abalike
