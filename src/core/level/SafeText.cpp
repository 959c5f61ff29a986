#include <abalike/level/SafeText.hpp>

#include <array>
#include <cstdio>

namespace abalike
{

namespace
{

/// Decodes the UTF-8 sequence at text[i]; length 0 when the byte does not start a well-formed one.
struct Decoded
{
    char32_t codePoint = 0;
    std::size_t length = 0;
};

Decoded decode(std::string_view text, std::size_t i)
{
    const auto byte = [&](std::size_t k)
    {
        return static_cast<unsigned char>(text[k]);
    };
    const unsigned char c = byte(i);
    if (c < 0x80)
        return {c, 1};
    std::size_t length = 0;
    char32_t value = 0;
    if (c >= 0xC2 && c <= 0xDF)
        length = 2, value = c & 0x1F;
    else if (c >= 0xE0 && c <= 0xEF)
        length = 3, value = c & 0x0F;
    else if (c >= 0xF0 && c <= 0xF4)
        length = 4, value = c & 0x07;
    else
        return {};
    if (i + length > text.size())
        return {};
    for (std::size_t k = 1; k < length; ++k)
    {
        if ((byte(i + k) & 0xC0) != 0x80)
            return {};
        value = (value << 6) | (byte(i + k) & 0x3F);
    }
    // Overlong forms, surrogates and values past U+10FFFF are not UTF-8.
    const char32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (value < smallest[length] || (value >= 0xD800 && value <= 0xDFFF) || value > 0x10FFFF)
        return {};
    return {value, length};
}

const char* characterName(char32_t c)
{
    static const std::array<const char*, 32> kC0{"null",
                                                 "start of heading",
                                                 "start of text",
                                                 "end of text",
                                                 "end of transmission",
                                                 "enquiry",
                                                 "acknowledge",
                                                 "bell",
                                                 "backspace",
                                                 "tab",
                                                 "newline",
                                                 "vertical tab",
                                                 "form feed",
                                                 "carriage return",
                                                 "shift out",
                                                 "shift in",
                                                 "data link escape",
                                                 "device control 1",
                                                 "device control 2",
                                                 "device control 3",
                                                 "device control 4",
                                                 "negative acknowledge",
                                                 "synchronous idle",
                                                 "end of transmission block",
                                                 "cancel",
                                                 "end of medium",
                                                 "substitute",
                                                 "escape",
                                                 "file separator",
                                                 "group separator",
                                                 "record separator",
                                                 "unit separator"};
    if (c < 0x20)
        return kC0[c];
    if (c == 0x7F)
        return "delete";
    if (c >= 0x80 && c <= 0x9F)
        return c == 0x9B ? "C1 control: control sequence introducer" : "C1 control";
    switch (c)
    {
    case 0x202A:
        return "left-to-right embedding";
    case 0x202B:
        return "right-to-left embedding";
    case 0x202C:
        return "pop directional formatting";
    case 0x202D:
        return "left-to-right override";
    case 0x202E:
        return "right-to-left override";
    case 0x2066:
        return "left-to-right isolate";
    case 0x2067:
        return "right-to-left isolate";
    case 0x2068:
        return "first strong isolate";
    case 0x2069:
        return "pop directional isolate";
    default:
        return nullptr;
    }
}

} // namespace

void appendUtf8(std::string& out, char32_t c)
{
    if (c < 0x80)
        out += static_cast<char>(c);
    else if (c < 0x800)
    {
        out += static_cast<char>(0xC0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
    else if (c < 0x10000)
    {
        out += static_cast<char>(0xE0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
    else
    {
        out += static_cast<char>(0xF0 | (c >> 18));
        out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
}

bool isUnsafeCharacter(char32_t c)
{
    return c < 0x20 || (c >= 0x7F && c <= 0x9F) || (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069);
}

std::optional<UnsafeCharacter> findUnsafeCharacter(std::string_view text)
{
    std::size_t index = 0;
    for (std::size_t i = 0; i < text.size(); ++index)
    {
        const Decoded d = decode(text, i);
        if (d.length == 0)
        {
            ++i;
            continue;
        }
        if (isUnsafeCharacter(d.codePoint))
            return UnsafeCharacter{index, d.codePoint};
        i += d.length;
    }
    return std::nullopt;
}

std::string describeCharacter(char32_t c)
{
    char code[16];
    std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(c));
    const char* name = characterName(c);
    return name == nullptr ? std::string(code) : std::string(code) + " (" + name + ")";
}

std::string escapeForTerminal(std::string_view text)
{
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();)
    {
        const Decoded d = decode(text, i);
        char escaped[16];
        if (d.length == 0 || (d.length == 1 && isUnsafeCharacter(d.codePoint)))
        {
            std::snprintf(escaped, sizeof escaped, "\\x%02X",
                          static_cast<unsigned>(static_cast<unsigned char>(text[i])));
            out += escaped;
            ++i;
        }
        else if (isUnsafeCharacter(d.codePoint))
        {
            std::snprintf(escaped, sizeof escaped, "\\u{%04X}", static_cast<unsigned>(d.codePoint));
            out += escaped;
            i += d.length;
        }
        else
        {
            out.append(text.substr(i, d.length));
            i += d.length;
        }
    }
    return out;
}

} // namespace abalike
