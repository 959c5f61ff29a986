#include "level/JsonLocator.hpp"

#include <abalike/level/SafeText.hpp>

#include <cstdlib>

namespace abalike
{

namespace
{
/// Deeper than any level file needs; the loader rejects deeper nesting before parsing.
constexpr int kMaxDepth = 256;

} // namespace

std::string jsonPointerToken(const std::string& key)
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
    // Decoded as the parser decodes it, so a key's pointer here is the pointer of the parsed document's key.
    std::string out;
    ++m_pos; // opening quote
    while (m_pos < m_text.size() && m_text[m_pos] != '"')
    {
        if (m_text[m_pos] != '\\' || m_pos + 1 >= m_text.size())
        {
            out += m_text[m_pos++];
            continue;
        }
        const char e = m_text[++m_pos];
        ++m_pos;
        switch (e)
        {
        case 'b':
            out += '\b';
            break;
        case 'f':
            out += '\f';
            break;
        case 'n':
            out += '\n';
            break;
        case 'r':
            out += '\r';
            break;
        case 't':
            out += '\t';
            break;
        case 'u':
        {
            unsigned long c = hex4();
            // A high surrogate followed by an escaped low one is one character beyond U+FFFF.
            if (c >= 0xD800 && c <= 0xDBFF && m_text.substr(m_pos, 2) == "\\u")
            {
                m_pos += 2;
                const unsigned long low = hex4();
                c = 0x10000 + ((c - 0xD800) << 10) + (low - 0xDC00);
            }
            appendUtf8(out, c);
            break;
        }
        default: // '"', '\\' and '/' stand for themselves
            out += e;
        }
    }
    ++m_pos; // closing quote
    return out;
}

unsigned long JsonLocator::hex4()
{
    const std::string digits(m_text.substr(m_pos, 4));
    m_pos += digits.size();
    return std::strtoul(digits.c_str(), nullptr, 16);
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
            const std::string child = pointer + "/" + jsonPointerToken(key);
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
