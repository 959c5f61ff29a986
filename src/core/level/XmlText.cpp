#include "level/XmlText.hpp"

#include <abalike/level/SafeText.hpp>

#include <algorithm>

namespace abalike
{

namespace
{

XmlText fromUtf16(std::string_view bytes, bool bigEndian, std::size_t start, std::string encoding)
{
    XmlText result;
    result.encoding = std::move(encoding);
    if ((bytes.size() - start) % 2 != 0)
    {
        result.error = "UTF-16 text with an odd number of bytes";
        result.errorOffset = bytes.size() - 1;
        return result;
    }
    const auto unit = [&](std::size_t i) -> char32_t
    {
        const auto a = static_cast<unsigned char>(bytes[i]);
        const auto b = static_cast<unsigned char>(bytes[i + 1]);
        return bigEndian ? (char32_t(a) << 8 | b) : (char32_t(b) << 8 | a);
    };
    for (std::size_t i = start; i < bytes.size(); i += 2)
    {
        char32_t c = unit(i);
        if (c >= 0xD800 && c <= 0xDBFF && i + 3 < bytes.size() && unit(i + 2) >= 0xDC00 && unit(i + 2) <= 0xDFFF)
        {
            c = 0x10000 + ((c - 0xD800) << 10) + (unit(i + 2) - 0xDC00);
            i += 2;
        }
        else if (c >= 0xD800 && c <= 0xDFFF)
        {
            result.error = "a lone UTF-16 surrogate";
            result.errorOffset = i;
            return result;
        }
        appendUtf8(result.utf8, c);
    }
    return result;
}

std::string withUnixLineEnds(std::string_view text)
{
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i)
    {
        if (text[i] == '\r')
        {
            out += '\n';
            if (i + 1 < text.size() && text[i + 1] == '\n')
                ++i;
        }
        else
            out += text[i];
    }
    return out;
}

bool isNameChar(char c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
           c == '.' || c == ':';
}

} // namespace

XmlText decodeXmlBytes(std::string_view bytes)
{
    XmlText result;
    const auto at = [&](std::size_t i)
    {
        return i < bytes.size() ? static_cast<unsigned char>(bytes[i]) : 0x100u;
    };
    if (at(0) == 0xFF && at(1) == 0xFE)
        result = fromUtf16(bytes, false, 2, "UTF-16LE with BOM");
    else if (at(0) == 0xFE && at(1) == 0xFF)
        result = fromUtf16(bytes, true, 2, "UTF-16BE with BOM");
    else if (at(0) == '<' && at(1) == 0)
        result = fromUtf16(bytes, false, 0, "UTF-16LE");
    else if (at(0) == 0 && at(1) == '<')
        result = fromUtf16(bytes, true, 0, "UTF-16BE");
    else if (at(0) == 0xEF && at(1) == 0xBB && at(2) == 0xBF)
    {
        result.utf8 = std::string(bytes.substr(3));
        result.encoding = "UTF-8 with BOM";
    }
    else
    {
        result.utf8 = std::string(bytes);
        result.encoding = "UTF-8";
    }
    if (result.error.empty())
        result.utf8 = withUnixLineEnds(result.utf8);
    return result;
}

TextPlace placeOf(std::string_view text, std::size_t offset)
{
    TextPlace place;
    offset = std::min(offset, text.size());
    for (std::size_t i = 0; i < offset; ++i)
    {
        if (text[i] == '\n')
        {
            ++place.line;
            place.column = 1;
        }
        else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) // count characters, not continuation bytes
            ++place.column;
    }
    return place;
}

std::vector<ClosedTag> closeOpenLeafTags(std::string& text, const std::vector<std::string>& leafNames)
{
    std::vector<ClosedTag> closed;
    std::string out;
    out.reserve(text.size() + 16);
    std::size_t i = 0;
    while (i < text.size())
    {
        if (text.compare(i, 4, "<!--") == 0)
        {
            const std::size_t end = text.find("-->", i + 4);
            const std::size_t stop = end == std::string::npos ? text.size() : end + 3;
            out.append(text, i, stop - i);
            i = stop;
            continue;
        }
        if (text[i] != '<')
        {
            out += text[i++];
            continue;
        }
        std::size_t nameEnd = i + 1;
        while (nameEnd < text.size() && isNameChar(text[nameEnd]))
            ++nameEnd;
        const std::string name = text.substr(i + 1, nameEnd - i - 1);
        if (std::find(leafNames.begin(), leafNames.end(), name) == leafNames.end())
        {
            out += text[i++];
            continue;
        }
        // The tag's end, outside quoted attribute values.
        std::size_t end = nameEnd;
        char quote = 0;
        while (end < text.size() && (quote != 0 || text[end] != '>'))
        {
            if (quote == 0 && (text[end] == '"' || text[end] == '\''))
                quote = text[end];
            else if (quote != 0 && text[end] == quote)
                quote = 0;
            ++end;
        }
        if (end >= text.size() || text[end - 1] == '/')
        {
            out.append(text, i, std::min(end + 1, text.size()) - i);
            i = end + 1;
            continue;
        }
        std::size_t next = end + 1;
        while (next < text.size() && (text[next] == ' ' || text[next] == '\t' || text[next] == '\n'))
            ++next;
        const bool endTagFollows = text.compare(next, name.size() + 2, "</" + name) == 0;
        out.append(text, i, end - i);
        if (!endTagFollows)
        {
            out += '/';
            closed.push_back({i, end, name});
        }
        out += '>';
        i = end + 1;
    }
    text = std::move(out);
    return closed;
}

std::size_t offsetBeforeRepair(std::size_t repaired, const std::vector<ClosedTag>& closed)
{
    // Each closed tag added one character just before its '>'; offsets after it moved by one.
    std::size_t added = 0;
    for (const ClosedTag& tag : closed)
        if (tag.insertAt + added < repaired)
            ++added;
    return repaired - added;
}

} // namespace abalike
