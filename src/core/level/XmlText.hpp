#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace abalike
{

/// XML text as the importer reads it: UTF-8 without a byte-order mark, lines ending in '\n'.
struct XmlText
{
    std::string utf8;
    std::string encoding; ///< what the bytes were: "UTF-8", "UTF-8 with BOM", "UTF-16LE", "UTF-16BE with BOM", ...
    std::string error;    ///< why the bytes are not text (a lone surrogate, an odd length); empty when they are
    std::size_t errorOffset = 0; ///< byte offset of that problem in the input
};

/// Decodes an XML file's bytes: UTF-8 or UTF-16 (either byte order, with or without a byte-order mark, told apart
/// by the NUL bytes around the first '<'), CRLF or CR line ends made LF.
XmlText decodeXmlBytes(std::string_view bytes);

/// 1-based line and column (in bytes) of an offset in text.
struct TextPlace
{
    int line = 1;
    int column = 1;
};
TextPlace placeOf(std::string_view text, std::size_t offset);

/// Science Birds writes some elements that hold nothing as start tags without an end (`<Slingshot x="-8"
/// y="-2.5">`), which its own reader accepts. Closes such start tags of the named elements (adds the '/' of
/// `<.../>`) unless their end tag follows, and returns where each one starts.
struct ClosedTag
{
    std::size_t offset = 0;   ///< of the '<', in the text before the repair
    std::size_t insertAt = 0; ///< of the '>' the '/' went before, in the text before the repair
    std::string name;
};
std::vector<ClosedTag> closeOpenLeafTags(std::string& text, const std::vector<std::string>& leafNames);

/// The offset in the text before closeOpenLeafTags of an offset in the repaired text.
std::size_t offsetBeforeRepair(std::size_t repaired, const std::vector<ClosedTag>& closed);

} // namespace abalike
