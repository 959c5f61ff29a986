#include "level/LevelReader.hpp"

#include <abalike/level/SafeText.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

namespace abalike
{

std::string describeJsonType(const nlohmann::json& value)
{
    switch (value.type())
    {
    case nlohmann::json::value_t::null:
        return "null";
    case nlohmann::json::value_t::object:
        return "an object";
    case nlohmann::json::value_t::array:
        return "an array";
    case nlohmann::json::value_t::string:
        return "the string " + value.dump();
    case nlohmann::json::value_t::boolean:
        return value.get<bool>() ? "true" : "false";
    default:
        return "the number " + value.dump();
    }
}

std::optional<std::string> closestMatch(const std::string& word, const std::vector<std::string>& candidates)
{
    std::optional<std::string> best;
    std::size_t bestDistance = std::max<std::size_t>(2, word.size() / 3) + 1;
    for (const std::string& candidate : candidates)
    {
        // Levenshtein distance, one row at a time.
        std::vector<std::size_t> row(candidate.size() + 1);
        for (std::size_t j = 0; j <= candidate.size(); ++j)
            row[j] = j;
        for (std::size_t i = 1; i <= word.size(); ++i)
        {
            std::size_t diagonal = row[0];
            row[0] = i;
            for (std::size_t j = 1; j <= candidate.size(); ++j)
            {
                const std::size_t up = row[j];
                const std::size_t cost = word[i - 1] == candidate[j - 1] ? 0 : 1;
                row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + cost});
                diagonal = up;
            }
        }
        if (row[candidate.size()] < bestDistance)
        {
            bestDistance = row[candidate.size()];
            best = candidate;
        }
    }
    return best;
}

void LevelReader::error(const std::string& pointer, const std::string& message)
{
    const auto [line, column] = m_locator.locate(pointer);
    m_issues.push_back({m_file, line, column, pointer, message});
}

void LevelReader::keyError(const std::string& pointer, const std::string& message)
{
    auto [line, column] = m_locator.locate(pointer + "#key");
    if (line == 0)
        std::tie(line, column) = m_locator.locate(pointer);
    m_issues.push_back({m_file, line, column, pointer, message});
}

bool LevelReader::object(const json& value, const std::string& pointer, std::initializer_list<const char*> allowed)
{
    if (!value.is_object())
    {
        error(pointer, "expected an object, got " + describeJsonType(value));
        return false;
    }
    const std::vector<std::string> names(allowed.begin(), allowed.end());
    for (const auto& [key, child] : value.items())
    {
        // A key with a control character is reported by safeText; calling it unknown as well would only repeat it.
        if (std::find(names.begin(), names.end(), key) != names.end() || findUnsafeCharacter(key))
            continue;
        std::string message = "unknown key \"" + key + "\"";
        if (const auto suggestion = closestMatch(key, names))
            message += " (did you mean \"" + *suggestion + "\"?)";
        else
        {
            message += " (expected one of:";
            for (const auto& n : names)
                message += " " + n;
            message += ")";
        }
        keyError(pointer + "/" + jsonPointerToken(key), message);
    }
    return true;
}

bool LevelReader::array(const json& value, const std::string& pointer)
{
    if (value.is_array())
        return true;
    error(pointer, "expected an array, got " + describeJsonType(value));
    return false;
}

bool LevelReader::array(const json& value, const std::string& pointer, std::size_t minItems, std::size_t maxItems,
                        const char* items)
{
    if (!value.is_array())
    {
        error(pointer, std::string("expected an array of ") + items + ", got " + describeJsonType(value));
        return false;
    }
    if (value.size() < minItems || value.size() > maxItems)
    {
        std::ostringstream message;
        message << "wrong number of " << items << " (expected ";
        if (minItems == maxItems)
            message << minItems;
        else
            message << minItems << " to " << maxItems;
        message << ", got " << value.size() << ")";
        error(pointer, message.str());
        return false;
    }
    return true;
}

std::vector<LevelIssue> LevelReader::take()
{
    std::stable_sort(m_issues.begin(), m_issues.end(),
                     [](const LevelIssue& a, const LevelIssue& b)
                     { return std::tie(a.line, a.column) < std::tie(b.line, b.column); });
    return std::move(m_issues);
}

void LevelReader::duplicateKeys()
{
    for (const std::string& pointer : m_locator.duplicateKeys())
        keyError(pointer, "duplicate key \"" + pointer.substr(pointer.rfind('/') + 1) +
                              "\" (expected each key once in an object; a JSON reader would silently keep the last)");
}

namespace
{

std::string unsafeMessage(const char* what, const UnsafeCharacter& bad)
{
    return std::string("unsafe character in ") + what +
           " (expected text without control or bidirectional characters, got " + describeCharacter(bad.codePoint) +
           " at character " + std::to_string(bad.index + 1) + ")";
}

} // namespace

void LevelReader::safeText(const json& root)
{
    // Iterative, so document depth never becomes stack depth.
    std::vector<std::pair<const json*, std::string>> pending{{&root, ""}};
    while (!pending.empty())
    {
        const auto [value, pointer] = pending.back();
        pending.pop_back();
        if (value->is_string())
        {
            if (const auto bad = findUnsafeCharacter(value->get_ref<const std::string&>()))
                error(pointer, unsafeMessage("a string", *bad));
        }
        else if (value->is_object())
            for (const auto& [key, child] : value->items())
            {
                const std::string childPointer = pointer + "/" + jsonPointerToken(key);
                if (const auto bad = findUnsafeCharacter(key))
                    keyError(childPointer, unsafeMessage("a key", *bad));
                pending.emplace_back(&child, childPointer);
            }
        else if (value->is_array())
            for (std::size_t i = 0; i < value->size(); ++i)
                pending.emplace_back(&(*value)[i], pointer + "/" + std::to_string(i));
    }
}

double LevelReader::number(const json& object, const std::string& pointer, const char* key, double fallback,
                           bool required, double min, double max)
{
    return number(object, pointer, key, fallback, required, NumberRange{min, max});
}

double LevelReader::number(const json& object, const std::string& pointer, const char* key, double fallback,
                           bool required, const NumberRange& range)
{
    const auto it = object.find(key);
    if (it == object.end())
    {
        if (required)
            error(pointer, std::string("missing required key \"") + key + "\" (expected a number)");
        return fallback;
    }
    return numberAt(*it, pointer + "/" + key, range).value_or(fallback);
}

std::optional<double> LevelReader::numberAt(const json& value, const std::string& pointer, const NumberRange& range)
{
    if (!value.is_number())
    {
        error(pointer, "expected a number, got " + describeJsonType(value));
        return std::nullopt;
    }
    const double number = value.get<double>();
    if (!std::isfinite(number))
    {
        // The parser turned a literal beyond a double's range into infinity; quote it as written.
        const std::string_view raw = m_locator.rawScalar(pointer);
        error(pointer, "expected a finite number, got " + (raw.empty() ? value.dump() : std::string(raw)) +
                           " (beyond the range of a double)");
        return std::nullopt;
    }
    if (number < range.min || number > range.max)
    {
        std::ostringstream message;
        message << range.what << " (expected " << range.min << " to " << range.max << (*range.unit ? " " : "")
                << range.unit << ", got " << number << ")";
        error(pointer, message.str());
        return std::nullopt;
    }
    return number;
}

std::string LevelReader::string(const json& object, const std::string& pointer, const char* key,
                                const std::string& fallback, bool required)
{
    const auto it = object.find(key);
    if (it == object.end())
    {
        if (required)
            error(pointer, std::string("missing required key \"") + key + "\" (expected a string)");
        return fallback;
    }
    if (!it->is_string())
    {
        error(pointer + "/" + key, "expected a string, got " + describeJsonType(*it));
        return fallback;
    }
    return it->get<std::string>();
}

} // namespace abalike
