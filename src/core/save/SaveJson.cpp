#include "save/SaveJson.hpp"

#include <abalike/save/SaveError.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace abalike
{

namespace
{

/// Save files nest three deep; the guard keeps a hostile file from costing deep recursion anywhere.
constexpr int kMaxSaveNesting = 16;

/// Deepest bracket nesting outside strings; stops counting once past the limit.
int nestingDepth(std::string_view text)
{
    int depth = 0;
    int deepest = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size() && deepest <= kMaxSaveNesting; ++i)
    {
        const char c = text[i];
        if (inString)
        {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
        }
        else if (c == '"')
            inString = true;
        else if (c == '{' || c == '[')
            deepest = std::max(deepest, ++depth);
        else if (c == '}' || c == ']')
            --depth;
    }
    return deepest;
}

/// A value as it appears in the file, shortened for a message.
std::string describe(const nlohmann::json& value)
{
    constexpr std::size_t kMaxChars = 40;
    std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    if (text.size() > kMaxChars)
        text = text.substr(0, kMaxChars) + "...";
    return text;
}

std::string formatNumber(double value)
{
    std::ostringstream text;
    text << value;
    return text.str();
}

/// nlohmann's messages start with "[json.exception.parse_error.101] "; players do not need that part.
std::string withoutPrefix(const std::string& message)
{
    const auto close = message.find("] ");
    return message.rfind("[json.exception.", 0) == 0 && close != std::string::npos ? message.substr(close + 2)
                                                                                   : message;
}

} // namespace

nlohmann::json parseSaveJson(std::string_view text, int expectedFormat, int oldestFormat)
{
    if (text.size() > kMaxSaveBytes)
        throw SaveFormatError("the file is " + std::to_string(text.size()) + " bytes; a save file is at most " +
                              std::to_string(kMaxSaveBytes));
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
        throw SaveFormatError("the file is empty");
    if (nestingDepth(text) > kMaxSaveNesting)
        throw SaveFormatError("the JSON nests more than " + std::to_string(kMaxSaveNesting) + " deep");
    nlohmann::json root;
    try
    {
        root = nlohmann::json::parse(text.begin(), text.end());
    }
    catch (const nlohmann::json::exception& e)
    {
        throw SaveFormatError("not valid JSON: " + withoutPrefix(e.what()));
    }
    if (!root.is_object())
        throw SaveFormatError(std::string("expected a JSON object, got ") + root.type_name());
    const auto format = root.find("format");
    if (format == root.end())
        throw SaveFormatError("missing \"format\"");
    const int version = readInt(*format, "/format", 0, std::numeric_limits<int>::max());
    const int oldest = oldestFormat > 0 ? std::min(oldestFormat, expectedFormat) : expectedFormat;
    if (version < oldest || version > expectedFormat)
        throw SaveFormatError("format " + std::to_string(version) + " is not supported (this abalike reads format " +
                              (oldest == expectedFormat
                                   ? std::to_string(expectedFormat)
                                   : std::to_string(oldest) + " to " + std::to_string(expectedFormat)) +
                              ")");
    return root;
}

int readInt(const nlohmann::json& value, const std::string& pointer, int min, int max)
{
    const auto fail = [&]
    {
        throw SaveFormatError(pointer + ": expected a whole number from " + std::to_string(min) + " to " +
                              std::to_string(max) + ", got " + describe(value));
    };
    if (value.is_number_unsigned())
    {
        const auto v = value.get<std::uint64_t>();
        if (v > static_cast<std::uint64_t>(max) || static_cast<std::int64_t>(v) < min)
            fail();
        return static_cast<int>(v);
    }
    if (!value.is_number_integer())
        fail();
    const auto v = value.get<std::int64_t>();
    if (v < min || v > max)
        fail();
    return static_cast<int>(v);
}

double readNumber(const nlohmann::json& value, const std::string& pointer, double min, double max)
{
    // JSON has no NaN or infinity and the parser rejects 1e400; the isfinite check keeps that true for any caller.
    const double v = value.is_number() ? value.get<double>() : std::numeric_limits<double>::quiet_NaN();
    if (!std::isfinite(v) || v < min || v > max)
        throw SaveFormatError(pointer + ": expected a number from " + formatNumber(min) + " to " + formatNumber(max) +
                              ", got " + describe(value));
    return v;
}

bool readBool(const nlohmann::json& value, const std::string& pointer)
{
    if (!value.is_boolean())
        throw SaveFormatError(pointer + ": expected true or false, got " + describe(value));
    return value.get<bool>();
}

const std::string& readString(const nlohmann::json& value, const std::string& pointer)
{
    if (!value.is_string())
        throw SaveFormatError(pointer + ": expected a string, got " + describe(value));
    return value.get_ref<const std::string&>();
}

std::string dumpSaveJson(const nlohmann::ordered_json& value)
{
    return value.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

} // namespace abalike
