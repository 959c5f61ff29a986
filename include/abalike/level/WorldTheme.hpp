#pragma once

#include <abalike/level/LevelDef.hpp>
#include <optional>
#include <string_view>
#include <vector>

namespace abalike
{

/// The world a level's scenery shows: sky, hills and ground are drawn in its colours. Only the look: the physics
/// comes from the level's environment.
enum class WorldTheme
{
    Earth,
    Moon,
    Mars,
    Titan,
    Jupiter,
};

/// "earth", "moon", "mars", "titan", "jupiter": the names of the level format's "theme".
const char* worldThemeName(WorldTheme theme);
/// "Earth", "Moon", ...: the world's name as a person writes it (the gravity preset's).
const char* worldThemeTitle(WorldTheme theme);
/// Every theme, in the order the editor lists them.
std::vector<WorldTheme> allWorldThemes();
/// The theme of that name; nullopt for any other text.
std::optional<WorldTheme> parseWorldTheme(std::string_view name);

/// The level's own theme if it names one; else the world whose gravity (GravityPresets) is within 5 % of the
/// level's, nearest first; else Earth.
WorldTheme levelTheme(const LevelDef& level);

} // namespace abalike
