#pragma once

#include <abalike/level/LevelDef.hpp>
#include <abalike/world/Catalog.hpp>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace abalike
{

/// Numbers in a level's `concept` and `hints` are filled from the level's own physics, not typed: a text says
/// "the red bird leaves at {v_max:red} m/s" and the reader sees "30.0". A placeholder is
///
///     {EXPRESSION}  or  {EXPRESSION|DECIMALS}
///
/// where EXPRESSION adds, subtracts, multiplies and divides values, numbers and sqrt(...), with parentheses and a
/// leading minus ("{v_max:blue / v_max:red|2}", "{gust_t:2 - gust_t:1}"), and a value
/// is a NAME or NAME:ARGUMENT from textValueNames() (a bird, material or pig of the catalog, or a gust step's
/// number). Without |DECIMALS a lone value uses its own decimals and an expression two. "{{" and "}}" are braces, and
/// so is a brace around anything but letters, digits, spaces and _ : | . + - * / ( ) ("{ like this, }" is text).
/// The values are those of the level as it plays: its slingshot, environment and material overrides.

/// One value a text can name.
struct TextValueName
{
    const char* name;
    const char* argument; ///< "BIRD", "MATERIAL", "PIG", "N" (a gust step, from 1), or "" for none
    const char* meaning;
    const char* unit;
    int decimals; ///< -1: as few as the value needs, at most 3
};

/// Every name, in the order the level guide lists them.
const std::vector<TextValueName>& textValueNames();

/// A placeholder that cannot be filled: what is wrong and at which character of the text (from 0).
class TextValueError : public std::runtime_error
{
public:
    TextValueError(const std::string& message, std::size_t offset) : std::runtime_error(message), m_offset(offset) {}
    std::size_t offset() const { return m_offset; }

private:
    std::size_t m_offset;
};

/// The value of NAME (with ARGUMENT, empty for none) for this level. Throws TextValueError (offset 0) for an unknown
/// name, a missing or unknown argument, or a value the level does not have (a gust step it lacks).
double textValue(const LevelDef& level, const Catalog& catalog, std::string_view name, std::string_view argument);

/// The text with every placeholder replaced by its value. Throws TextValueError.
std::string fillText(std::string_view text, const LevelDef& level, const Catalog& catalog);

/// Checks every placeholder's syntax, names and arguments without computing the flight values (cheap enough for
/// the level reader). Returns the errors; empty when the text fills.
std::vector<TextValueError> checkText(std::string_view text, const LevelDef& level, const Catalog& catalog);

/// The value of one expression of the placeholders' grammar, without braces ("best_angle:red - 2"). Throws
/// TextValueError with the offset in the expression.
double evaluateExpression(std::string_view expression, const LevelDef& level, const Catalog& catalog);

/// Checks an expression's syntax, names and arguments without computing anything.
std::optional<TextValueError> checkExpression(std::string_view expression, const LevelDef& level,
                                              const Catalog& catalog);

/// fillText, or the text as written when a placeholder does not fill (the reader rejects such a file, so this is
/// only for a level built in code): what the game shows.
std::string levelText(std::string_view text, const LevelDef& level, const Catalog& catalog);

/// Earth's standard values the texts compare other worlds with (names earth_g and earth_rho).
inline constexpr double kEarthGravity = 9.81;
inline constexpr double kEarthAirDensity = 1.2;

} // namespace abalike
