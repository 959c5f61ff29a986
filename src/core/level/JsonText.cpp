#include "level/JsonText.hpp"

#include "level/JsonLocator.hpp"

#include <abalike/level/LevelIO.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace abalike
{

namespace
{

[[noreturn]] void fail(const std::string& file, std::pair<int, int> where, const std::string& message)
{
    throw LevelLoadError({LevelIssue{file, where.first, where.second, "", message}});
}

/// Offset of the first byte that is not part of well-formed UTF-8 (RFC 3629: no overlongs, no surrogates,
/// nothing above U+10FFFF), or npos.
std::size_t firstInvalidUtf8(std::string_view text)
{
    const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
    std::size_t i = 0;
    while (i < text.size())
    {
        const unsigned char c = bytes[i];
        if (c < 0x80)
        {
            ++i;
            continue;
        }
        std::size_t length = 0;
        unsigned char low = 0x80;
        unsigned char high = 0xBF;
        if (c >= 0xC2 && c <= 0xDF)
            length = 2;
        else if (c >= 0xE0 && c <= 0xEF)
        {
            length = 3;
            low = c == 0xE0 ? 0xA0 : 0x80;
            high = c == 0xED ? 0x9F : 0xBF;
        }
        else if (c >= 0xF0 && c <= 0xF4)
        {
            length = 4;
            low = c == 0xF0 ? 0x90 : 0x80;
            high = c == 0xF4 ? 0x8F : 0xBF;
        }
        else
            return i;
        if (i + length > text.size())
            return i;
        if (bytes[i + 1] < low || bytes[i + 1] > high)
            return i;
        for (std::size_t k = 2; k < length; ++k)
            if (bytes[i + k] < 0x80 || bytes[i + k] > 0xBF)
                return i;
        i += length;
    }
    return std::string_view::npos;
}

/// Offset where bracket nesting first goes deeper than maxNesting (outside strings), or npos.
std::size_t tooDeep(std::string_view text, int maxNesting)
{
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i)
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
        else if ((c == '{' || c == '[') && ++depth > maxNesting)
            return i;
        else if (c == '}' || c == ']')
            --depth;
    }
    return std::string_view::npos;
}

/// nlohmann reports the byte after the offending token; editors want its first character.
std::size_t tokenStart(std::string_view text, std::size_t byteAfter)
{
    const std::size_t end = std::min(byteAfter, text.size());
    if (end == 0)
        return 0;
    std::size_t i = end - 1;
    if (text[i] == '"')
    {
        // Back to the opening quote of this string.
        while (i > 0 && !(text[i - 1] == '"' && (i < 2 || text[i - 2] != '\\')))
            --i;
        return i > 0 ? i - 1 : 0;
    }
    while (i > 0 && (std::isalnum(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '.' ||
                     text[i - 1] == '-' || text[i - 1] == '+'))
        --i;
    return i;
}

/// The usual reason behind a syntax error at offset, in a designer's words; empty if none fits.
std::string syntaxHint(std::string_view text, std::size_t at, std::size_t parserByte, const std::string& reason)
{
    if (parserByte >= text.size())
        return "the file ends before the JSON is complete (expected more, got the end of the file; truncated?)";
    const std::string_view rest = text.substr(std::min(at, text.size()));
    const char c = rest.empty() ? '\0' : rest.front();
    std::size_t before = at;
    while (before > 0 && std::isspace(static_cast<unsigned char>(text[before - 1])))
        --before;
    const char previous = before > 0 ? text[before - 1] : '\0';
    if (c == '/')
        return "comments are not allowed in JSON (expected a value or a key, got '/')";
    if (c == '\'')
        return "strings need double quotes (expected '\"', got '\'')";
    for (const char* word : {"NaN", "nan", "Infinity", "-Infinity", "inf", "-inf"})
        if (rest.substr(0, std::string_view(word).size()) == word)
            return std::string("not a JSON number (expected a finite number, got ") + word + ")";
    if ((c == ']' || c == '}') && previous == ',')
        return std::string("trailing comma (expected another value after ',', got '") + c + "')";
    if (reason.find("unexpected string literal") != std::string::npos && previous != ',' && previous != '{' &&
        previous != '[')
        return "missing comma (expected ',' between two values, got the next value)";
    return "";
}

/// Offset of the first number literal outside strings that overflows a double, or npos.
std::size_t overflowingNumber(std::string_view text)
{
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i)
    {
        const char c = text[i];
        if (inString)
        {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
            continue;
        }
        if (c == '"')
        {
            inString = true;
            continue;
        }
        if (c != '-' && !std::isdigit(static_cast<unsigned char>(c)))
            continue;
        std::size_t end = i + 1;
        while (end < text.size() && (std::isdigit(static_cast<unsigned char>(text[end])) || text[end] == '.' ||
                                     text[end] == 'e' || text[end] == 'E' || text[end] == '+' || text[end] == '-'))
            ++end;
        const std::string token(text.substr(i, end - i));
        const double value = std::strtod(token.c_str(), nullptr);
        if (std::isinf(value))
            return i;
        i = end - 1;
    }
    return std::string_view::npos;
}

std::string bytesText(std::uintmax_t bytes)
{
    return std::to_string(bytes) + " bytes";
}

} // namespace

nlohmann::json parseJsonText(std::string_view text, const std::string& fileName, const JsonTextLimits& limits)
{
    if (text.size() > limits.maxBytes)
        fail(fileName, {1, 1},
             "file too large (expected " + std::string(limits.what) + " of at most " + bytesText(limits.maxBytes) +
                 ", got " + bytesText(text.size()) + ")");
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
        fail(fileName, {1, 1},
             "empty file (expected a JSON object describing " + std::string(limits.what) + ", got " +
                 (text.empty() ? "no bytes" : "only white space") + ")");
    if (const std::size_t bad = firstInvalidUtf8(text); bad != std::string_view::npos)
    {
        char byte[8];
        std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(text[bad])));
        fail(fileName, JsonLocator::lineColumn(text, bad),
             std::string("invalid UTF-8 (expected a UTF-8 text file, got byte ") + byte +
                 "; is this a binary file, or saved in another encoding?)");
    }
    if (const std::size_t deep = tooDeep(text, limits.maxNesting); deep != std::string_view::npos)
        fail(fileName, JsonLocator::lineColumn(text, deep),
             "JSON nested too deeply (expected at most " + std::to_string(limits.maxNesting) +
                 " levels of [ and {, got more)");
    try
    {
        return nlohmann::json::parse(text);
    }
    catch (const nlohmann::json::parse_error& e)
    {
        std::string what = e.what();
        // nlohmann prefixes "[json.exception.parse_error.101] parse error at line 1, column 2: "; keep the reason.
        if (const auto colon = what.find(": "); colon != std::string::npos)
            what = what.substr(colon + 2);
        const std::size_t at = tokenStart(text, e.byte);
        const std::string hint = syntaxHint(text, at, e.byte, what);
        fail(fileName, JsonLocator::lineColumn(text, at),
             "invalid JSON: " + (hint.empty() ? what : hint + "; parser: " + what));
    }
    catch (const nlohmann::json::out_of_range& e)
    {
        // A literal like 1e400: the parser refuses it without saying where.
        const std::size_t at = overflowingNumber(text);
        const std::size_t end = at == std::string_view::npos ? at : text.find_first_of(",}] \t\r\n", at);
        const std::string literal = at == std::string_view::npos
                                        ? "a number"
                                        : std::string(text.substr(at, end == std::string_view::npos ? end : end - at));
        fail(fileName, at == std::string_view::npos ? std::pair{1, 1} : JsonLocator::lineColumn(text, at),
             "number beyond the range of a double (expected a finite number, got " + literal + ")");
    }
    catch (const nlohmann::json::exception& e)
    {
        fail(fileName, {1, 1}, std::string("invalid JSON: ") + e.what());
    }
}

std::string readJsonFile(const std::string& path, const JsonTextLimits& limits)
{
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw LevelLoadError({LevelIssue{path, 0, 0, "", "is a directory (expected a .json file)"}});
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw LevelLoadError({LevelIssue{path, 0, 0, "", "cannot open file (does it exist and is it readable?)"}});
    std::string text;
    char buffer[65536];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
    {
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
        if (text.size() > limits.maxBytes)
        {
            // No need to read a huge file to the end: report its real size and stop.
            const auto size = std::filesystem::file_size(path, ec);
            fail(path, {1, 1},
                 "file too large (expected " + std::string(limits.what) + " of at most " + bytesText(limits.maxBytes) +
                     ", got " + (ec ? "more" : bytesText(size)) + ")");
        }
    }
    return text;
}

} // namespace abalike
