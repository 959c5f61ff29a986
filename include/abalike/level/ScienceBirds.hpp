#pragma once

#include <abalike/level/LevelIO.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace abalike
{

class Catalog;

/// A Science Birds level converted to ours, and what the conversion changed or guessed.
struct ScienceBirdsLevel
{
    LevelDef level;
    /// Each located in the XML file (line, column) and naming the body of the new level it concerns (pointer):
    /// snaps onto supports, a TriangleHole made solid, an unclosed element, a missing optional attribute, ...
    std::vector<LevelIssue> warnings;
};

/// How to convert.
struct ScienceBirdsOptions
{
    bool sandbox = false; ///< write a sandbox scene (it may have no pig): a structure for the editor
};

/// Converts a Science Birds level: the XML that the Science Birds game and the AIBIRDS level-generation competitions
/// use (`<Level>` with `<Birds>` or `<BirdsAmount>`, `<Slingshot>`, `<GameObjects>` of `Block`, `Pig`, `TNT` and
/// `Platform`), in UTF-8 or UTF-16 with or without a byte-order mark, CRLF or LF. Sizes are Science Birds' own
/// (1 unit = 1 m); its ground at y = -3.5 becomes ours at 0, x stays; x and y are centres. Bodies that float or sink
/// by up to kSnapM are set onto what is under them, bottom to top, each reported. A file whose lowest bodies all
/// stand the same height above that ground, more than kSnapM (the hand-made levels of Science Birds' repository,
/// whose ground is higher), is read with that ground instead, with one warning saying so. What Science Birds itself
/// accepts (an element left unclosed, a missing rotation or material) is read with a warning; everything else throws
/// LevelLoadError with the file's line and column. levels/README.md documents the mapping.
ScienceBirdsLevel importScienceBirds(std::string_view bytes, const std::string& fileName, const Catalog& catalog,
                                     const ScienceBirdsOptions& options = {});

/// Science Birds builds its levels a few centimetres apart and lets them fall into place; the import does it for
/// gaps up to this (its own hand-made level-4 has bodies 11 and 15 cm up).
inline constexpr double kScienceBirdsSnapM = 0.2;

/// Science Birds' ground line.
inline constexpr double kScienceBirdsGroundY = -3.5;

} // namespace abalike
