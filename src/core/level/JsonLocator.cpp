#include "level/JsonLocator.hpp"

namespace abalike
{

namespace
{
/// Deeper than any level file needs; the loader rejects deeper nesting before parsing.
constexpr int kMaxDepth = 256;

std::string escapePointerToken(const std::string& key)
{
    std::string out;
    for (char c : key)
    {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}
} // namespace

JsonLocator::JsonLocator(std::string_view text) : m_text(text)
{
    skipSpace();
    if (m_pos < m_text.size())
        scanValue("");
}

std::pair<int, int> JsonLocator::locate(const std::string& pointer) const
{
    std::string p = pointer;
    while (true)
    {
        if (const auto it = m_offsets.find(p); it != m_offsets.end())
            return lineColumn(m_text, it->second);
        if (p.empty())
            return {0, 0};
        p.erase(p.rfind('/'));
    }
}

std::pair<int, int> JsonLocator::lineColumn(std::string_view text, std::size_t offset)
{
    int line = 1;
    int column = 1;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i)
    {
        if (text[i] == '\n')
        {
            ++line;
            column = 1;
        }
        else
            ++column;
    }
    return {line, column};
}

std::string_view JsonLocator::rawScalar(const std::string& pointer) const
{
    const auto it = m_offsets.find(pointer);
    if (it == m_offsets.end())
        return {};
    std::size_t end = it->second;
    while (end < m_text.size() && std::string_view(",}] \n\r\t").find(m_text[end]) == std::string_view::npos)
        ++end;
    return m_text.substr(it->second, end - it->second);
}

void JsonLocator::skipSpace()
{
    while (m_pos < m_text.size() &&
           (m_text[m_pos] == ' ' || m_text[m_pos] == '\n' || m_text[m_pos] == '\r' || m_text[m_pos] == '\t'))
        ++m_pos;
}

std::string JsonLocator::scanString()
{
    // Keys are compared with the parsed document's keys; escapes other than \" and \\ are kept raw, which
    // only matters for keys no level uses.
    std::string out;
    ++m_pos; // opening quote
    while (m_pos < m_text.size() && m_text[m_pos] != '"')
    {
        if (m_text[m_pos] == '\\' && m_pos + 1 < m_text.size())
        {
            ++m_pos;
            out += m_text[m_pos] == '"' || m_text[m_pos] == '\\' ? m_text[m_pos] : '?';
        }
        else
            out += m_text[m_pos];
        ++m_pos;
    }
    ++m_pos; // closing quote
    return out;
}

void JsonLocator::scanValue(const std::string& pointer)
{
    m_offsets.emplace(pointer, m_pos);
    if (m_pos >= m_text.size() || ++m_depth > kMaxDepth)
        return;
    const char c = m_text[m_pos];
    if (c == '{')
    {
        ++m_pos;
        skipSpace();
        while (m_pos < m_text.size() && m_text[m_pos] != '}')
        {
            const std::size_t keyPos = m_pos + 1; // a key's errors point at its name, inside the quotes
            const std::string key = scanString();
            const std::string child = pointer + "/" + escapePointerToken(key);
            skipSpace();
            ++m_pos; // ':'
            skipSpace();
            if (m_offsets.count(child + "#key") != 0)
                m_duplicates.push_back(child);
            scanValue(child);
            m_offsets.emplace(child + "#key", keyPos);
            skipSpace();
            if (m_pos < m_text.size() && m_text[m_pos] == ',')
            {
                ++m_pos;
                skipSpace();
            }
        }
        ++m_pos;
    }
    else if (c == '[')
    {
        ++m_pos;
        skipSpace();
        for (int index = 0; m_pos < m_text.size() && m_text[m_pos] != ']'; ++index)
        {
            scanValue(pointer + "/" + std::to_string(index));
            skipSpace();
            if (m_pos < m_text.size() && m_text[m_pos] == ',')
            {
                ++m_pos;
                skipSpace();
            }
        }
        ++m_pos;
    }
    else if (c == '"')
        scanString();
    else
    {
        while (m_pos < m_text.size() && m_text[m_pos] != ',' && m_text[m_pos] != '}' && m_text[m_pos] != ']' &&
               m_text[m_pos] != ' ' && m_text[m_pos] != '\n' && m_text[m_pos] != '\r' && m_text[m_pos] != '\t')
            ++m_pos;
    }
    --m_depth;
}

} // namespace abalike
