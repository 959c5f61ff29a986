#include <abalike/flight/GravityPresets.hpp>
#include <abalike/level/WorldTheme.hpp>
#include <array>
#include <cmath>

namespace abalike
{

namespace
{
struct ThemeName
{
    WorldTheme theme;
    const char* name;
    const char* preset; ///< the GravityPresets entry whose gravity picks it
};

constexpr std::array<ThemeName, 5> kThemes{{
    {WorldTheme::Earth, "earth", "Earth"},
    {WorldTheme::Moon, "moon", "Moon"},
    {WorldTheme::Mars, "mars", "Mars"},
    {WorldTheme::Titan, "titan", "Titan"},
    {WorldTheme::Jupiter, "jupiter", "Jupiter"},
}};

/// Gravity within this share of a world's picks that world's look.
constexpr double kGravityTolerance = 0.05;
} // namespace

const char* worldThemeName(WorldTheme theme)
{
    for (const ThemeName& t : kThemes)
        if (t.theme == theme)
            return t.name;
    return "earth";
}

const char* worldThemeTitle(WorldTheme theme)
{
    for (const ThemeName& t : kThemes)
        if (t.theme == theme)
            return t.preset;
    return "Earth";
}

std::vector<WorldTheme> allWorldThemes()
{
    std::vector<WorldTheme> themes;
    for (const ThemeName& t : kThemes)
        themes.push_back(t.theme);
    return themes;
}

std::optional<WorldTheme> parseWorldTheme(std::string_view name)
{
    for (const ThemeName& t : kThemes)
        if (name == t.name)
            return t.theme;
    return std::nullopt;
}

WorldTheme levelTheme(const LevelDef& level)
{
    if (level.theme)
        return *level.theme;
    const double g = level.environment.gravity;
    WorldTheme best = WorldTheme::Earth;
    double bestShare = kGravityTolerance;
    for (const GravityPreset& preset : gravityPresets())
    {
        const double share = std::abs(g - preset.gravity) / preset.gravity;
        if (share > bestShare)
            continue;
        for (const ThemeName& t : kThemes)
            if (preset.name == t.preset)
            {
                best = t.theme;
                bestShare = share;
            }
    }
    return best;
}

} // namespace abalike
