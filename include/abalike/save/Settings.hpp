#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace abalike
{

/// Colours the game draws with. ColourBlindSafe avoids red/green distinctions and tells materials apart by
/// pattern as well as colour.
enum class Palette
{
    Standard,
    ColourBlindSafe,
};

/// The name of a palette in settings.json ("standard", "colour_blind_safe").
const char* paletteName(Palette palette);

/// How much of the RK4 preview is drawn while aiming.
enum class PreviewMode
{
    Full,  ///< the whole path to the first contact, with the contact ring
    Short, ///< the dots of the climb to the top of the arc (at least half a second): the aim, not the answer
    Off,
};

/// "full", "short" or "off", as in settings.json.
const char* previewModeName(PreviewMode mode);

/// How the game words its physics. School (ages 14-16, the default) names the ideas without the numerical
/// machinery: no "RK4", "Box2D", "TOI" or "chord cast" in any text, and the integrator tools (the RK4 walkthrough,
/// the integrator comparison) are left out. University shows everything at full depth.
enum class Wording
{
    School,
    University,
};

/// "school" or "university", as in settings.json and --wording.
const char* wordingName(Wording wording);
/// The wording of that name; nullopt for any other text.
std::optional<Wording> parseWording(std::string_view name);

/// What a level shows. Game: the genre's play (a short arc of preview dots, a power bar, no physics sentences or
/// formulas). Learn: the teaching game (the full preview, the numbers with units, a sentence of physics after every
/// shot). The teaching overlay (T) opens in either; the tutorial and the lessons always run in Learn.
enum class PlayMode
{
    Game,
    Learn,
};

/// "game" or "learn", as in settings.json and --mode.
const char* playModeName(PlayMode mode);
/// The mode of that name; nullopt for any other text.
std::optional<PlayMode> parsePlayMode(std::string_view name);

/// The player's preferences. Every field has a default, and a settings file may leave any of them out.
struct Settings
{
    double musicVolume = 0.7;                ///< 0 to 1
    double effectsVolume = 1.0;              ///< 0 to 1
    PlayMode mode = PlayMode::Game;          ///< what a level shows ("mode"; --mode wins for a run)
    PreviewMode preview = PreviewMode::Full; ///< Learn's preview while aiming ("preview"; older files' show_preview)
    PreviewMode gamePreview = PreviewMode::Short; ///< Game's preview while aiming ("game_preview")
    bool showActualPath = true;                   ///< trace the path the bird really flew
    bool fullscreen = false;
    unsigned windowWidth = 1280; ///< 320 to 7680 pixels
    unsigned windowHeight = 720; ///< 240 to 4320 pixels
    bool mute = false;           ///< no sound at all, whatever the volumes
    double textScale = 1.0;      ///< 1 to 2: every UI text is drawn this much larger
    Palette palette = Palette::Standard;
    bool highContrast = false;    ///< solid panels, stronger outlines, text contrast of at least 7:1
    bool reducedMotion = false;   ///< no camera shake, fewer particles, no parallax drift
    bool teachingOverlay = false; ///< force arrows, energy bars and the other teaching aids on the play screen
    bool openAllLevels = false;   ///< every campaign level playable (a class); progress and stars are still kept
    Wording wording = Wording::School;

    /// The preview each mode keeps: a saved "preview" from an earlier version stays with Learn.
    PreviewMode previewFor(PlayMode playMode) const { return playMode == PlayMode::Game ? gamePreview : preview; }
    PreviewMode& previewFor(PlayMode playMode) { return playMode == PlayMode::Game ? gamePreview : preview; }

    bool operator==(const Settings&) const = default;
};

/// Parses the text of settings.json. Throws SaveFormatError saying what is wrong and where.
Settings parseSettings(std::string_view text);

/// The text of settings.json.
std::string settingsToJson(const Settings& settings);

} // namespace abalike
