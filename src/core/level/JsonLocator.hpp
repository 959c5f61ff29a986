#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace abalike
{

/// Line and column (1-based) of every value in a JSON text, by JSON pointer, so errors found after parsing
/// can point at the place in the file. nlohmann::json keeps no positions; this scans the text once.
class JsonLocator
{
public:
    /// The text must already have parsed as JSON.
    explicit JsonLocator(std::string_view text);

    /// Line and column of the value at pointer, or of its closest located parent; {0, 0} if none.
    std::pair<int, int> locate(const std::string& pointer) const;

    /// Line and column of a byte offset (1-based; columns count bytes).
    static std::pair<int, int> lineColumn(std::string_view text, std::size_t offset);

    /// The source text of the scalar at pointer (a number as written, e.g. "1e400"); empty if not located.
    std::string_view rawScalar(const std::string& pointer) const;

    /// Pointers of keys that appear more than once in their object (JSON parsers silently keep the last).
    const std::vector<std::string>& duplicateKeys() const { return m_duplicates; }

private:
    void scanValue(const std::string& pointer);
    void skipSpace();
    std::string scanString();
    unsigned long hex4(); ///< the four hex digits of a \u escape at m_pos

    std::string_view m_text;
    std::size_t m_pos = 0;
    int m_depth = 0;
    std::unordered_map<std::string, std::size_t> m_offsets;
    std::vector<std::string> m_duplicates;
};

/// A key as one token of a JSON pointer (RFC 6901: "~" as "~0", "/" as "~1").
std::string jsonPointerToken(const std::string& key);

} // namespace abalike
