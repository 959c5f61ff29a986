#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace abalike
{

/// Appends a code point (at most U+10FFFF) as UTF-8.
void appendUtf8(std::string& out, char32_t codePoint);

/// A character a level or campaign string may not hold, and where it is.
struct UnsafeCharacter
{
    std::size_t index = 0; ///< 0-based, in characters (code points) from the start of the string
    char32_t codePoint = 0;
};

/// True for the characters no string in a level or campaign manifest may hold, because they change what a terminal
/// or a text view shows: C0 controls (tab and newline included), DEL and C1 controls (U+0000-U+001F,
/// U+007F-U+009F), and the bidirectional embeddings, overrides and isolates (U+202A-U+202E, U+2066-U+2069).
bool isUnsafeCharacter(char32_t codePoint);

/// The first unsafe character in UTF-8 text, if any (bytes that are not UTF-8 are skipped: the loader rejects
/// them before it looks at strings).
std::optional<UnsafeCharacter> findUnsafeCharacter(std::string_view text);

/// "U+001B (escape)": a code point for a message, with its name when it is an unsafe one.
std::string describeCharacter(char32_t codePoint);

/// Text from a file or the command line made safe to print on a terminal: unsafe characters and bytes that are not
/// UTF-8 become \xHH (one byte: C0, DEL, stray bytes) or \u{HHHH} (C1 and bidirectional controls); everything
/// else, including a backslash, is kept, so ordinary text is unchanged and escaping twice changes nothing more.
std::string escapeForTerminal(std::string_view text);

} // namespace abalike
