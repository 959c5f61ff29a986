#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace abalike
{

/// Parses a save file's JSON: at most kMaxSaveBytes, shallow, an object whose "format" is the expected version
/// (or, with oldestFormat, any version from oldestFormat to expectedFormat: the caller migrates older ones).
/// Throws SaveFormatError with a message a player can pass on to us.
nlohmann::json parseSaveJson(std::string_view text, int expectedFormat, int oldestFormat = 0);

/// Members of a save file's object; each throws SaveFormatError naming /key and what was expected.
int readInt(const nlohmann::json& value, const std::string& pointer, int min, int max);
double readNumber(const nlohmann::json& value, const std::string& pointer, double min, double max);
bool readBool(const nlohmann::json& value, const std::string& pointer);
const std::string& readString(const nlohmann::json& value, const std::string& pointer);

/// The text of a save file: two-space indent, a final newline, bad UTF-8 replaced rather than thrown.
std::string dumpSaveJson(const nlohmann::ordered_json& value);

/// A save file is a few kB; anything this large is not one of ours.
inline constexpr std::size_t kMaxSaveBytes = 4u << 20;

} // namespace abalike
