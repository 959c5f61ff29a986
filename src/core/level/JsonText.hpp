#pragma once

#include <abalike/level/LevelLimits.hpp>

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace abalike
{

/// Limits on a JSON text checked before it is parsed, so hostile input fails fast with a clear message.
struct JsonTextLimits
{
    std::size_t maxBytes = 4u << 20;
    int maxNesting = 64;
    const char* what = "a level"; ///< what the file should be, for messages
};

/// The limits of a level file (the level loader and the campaign's sandbox check read levels alike).
inline constexpr JsonTextLimits kLevelText{limits::kMaxLevelBytes, limits::kMaxNesting, "a level"};
inline constexpr JsonTextLimits kManifestText{1u << 20, 16, "a campaign manifest"};

/// Parses JSON text for the level loader: size, emptiness, UTF-8 and nesting are checked before the parser sees
/// it, and syntax errors name the line and column of the offending token. Throws LevelLoadError with one issue.
nlohmann::json parseJsonText(std::string_view text, const std::string& fileName, const JsonTextLimits& limits);

/// Reads a whole file for parseJsonText, stopping early past maxBytes (the size is then reported from the file
/// system). Throws LevelLoadError when the file cannot be read or is too large.
std::string readJsonFile(const std::string& path, const JsonTextLimits& limits);

} // namespace abalike
