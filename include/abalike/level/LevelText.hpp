#pragma once

#include <abalike/level/LevelIO.hpp>
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace abalike
{

/// Fills in the line and column of each issue from its JSON pointer in the level file's text (valid JSON), and the
/// file name; issues whose pointer is not in the text keep 0.
void locateIssues(std::vector<LevelIssue>& issues, std::string_view text, const std::string& file);

/// The text with the number at pointer (e.g. /blocks/3/y) replaced by `number`, everything else byte for byte as
/// it was (a hand-written file keeps its layout). Throws std::invalid_argument when the pointer is not a number.
std::string replaceNumber(std::string_view text, const std::string& pointer, const std::string& number);

/// The text with the level's "stars" set to these thresholds: the three numbers replaced where the file has them,
/// else the key added before the closing brace; everything else byte for byte as it was.
std::string withStars(std::string_view text, const std::array<int, 3>& stars);

/// The file's "$schema" reference, or "" (what `abalike fmt` writes back).
std::string schemaReferenceOf(std::string_view text);

} // namespace abalike
