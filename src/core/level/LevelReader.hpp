#pragma once

#include "level/JsonLocator.hpp"

#include <abalike/level/LevelIO.hpp>

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace abalike
{

/// The values a number field accepts, and how to explain a value outside them.
struct NumberRange
{
    double min = 0.0;
    double max = 0.0;
    const char* unit = "";             ///< printed after the bounds, e.g. "m"
    const char* what = "out of range"; ///< what is wrong with a value outside, e.g. "too large for a moving body"
};

/// Reads typed fields out of parsed JSON, collecting every problem (with its pointer and position) instead of
/// stopping at the first.
class LevelReader
{
public:
    using json = nlohmann::json;

    LevelReader(std::string file, const JsonLocator& locator) : m_file(std::move(file)), m_locator(locator) {}

    void error(const std::string& pointer, const std::string& message);
    /// Reports an error at the position of the key itself (for unknown keys).
    void keyError(const std::string& pointer, const std::string& message);

    /// True if value is an object; reports unknown keys (with a suggestion) against the allowed list.
    bool object(const json& value, const std::string& pointer, std::initializer_list<const char*> allowed);
    bool array(const json& value, const std::string& pointer);
    /// True if value is an array of minItems to maxItems elements (reports either problem).
    bool array(const json& value, const std::string& pointer, std::size_t minItems, std::size_t maxItems,
               const char* items);

    /// Reads a finite number in [min, max]; reports and returns fallback when missing (if required) or wrong.
    double number(const json& object, const std::string& pointer, const char* key, double fallback, bool required,
                  double min, double max);
    double number(const json& object, const std::string& pointer, const char* key, double fallback, bool required,
                  const NumberRange& range);
    /// Reads the array element or value at pointer itself as a finite number in range.
    std::optional<double> numberAt(const json& value, const std::string& pointer, const NumberRange& range);
    std::string string(const json& object, const std::string& pointer, const char* key, const std::string& fallback,
                       bool required);

    /// Reports every key the document repeats inside one object.
    void duplicateKeys();

    /// The problems found, in the order they appear in the file.
    std::vector<LevelIssue> take();
    bool ok() const { return m_issues.empty(); }
    /// How many problems were found so far.
    std::size_t issueCount() const { return m_issues.size(); }

private:
    std::string m_file;
    const JsonLocator& m_locator;
    std::vector<LevelIssue> m_issues;
};

/// Describes the JSON type of a value for messages ("a string", "an array", ...).
std::string describeJsonType(const nlohmann::json& value);

/// The closest of the candidates to word by edit distance, if close enough to be a likely typo.
std::optional<std::string> closestMatch(const std::string& word, const std::vector<std::string>& candidates);

} // namespace abalike
