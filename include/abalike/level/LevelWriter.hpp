#pragma once

#include <abalike/level/LevelDef.hpp>

#include <filesystem>
#include <string>

namespace abalike
{

/// A block shape's name in level files: "box", "circle", "triangle", "hollow_box".
const char* blockShapeName(BlockShape shape);

/// Shortest text that reads back as the same double; whole numbers without a fraction ("22", not "22.0"), -0 as
/// "0": how levels write numbers, and how messages quote them.
std::string shortestNumber(double value);

/// The level as JSON text in the documented format (levels/README.md): keys in the guide's order, optional fields
/// only where they differ from their defaults, numbers in their shortest form that reads back to the same double,
/// one block, pig or terrain piece per line. Saving, loading and saving again gives the same bytes.
std::string writeLevelJson(const LevelDef& level, const std::string& schemaReference);

/// The "$schema" value for a level saved at levelPath: the schema's path relative to the level's folder
/// ("schema/level.schema.json" next to the campaign), or absolute where no relative path exists.
std::string schemaReferenceFor(const std::filesystem::path& levelPath, const std::filesystem::path& schemaPath);

/// Writes the level to path atomically (temporary file, fsync, rename; see writeFileAtomically), its "$schema"
/// pointing at schemaPath. Throws SaveIoError naming the file and the reason.
void saveLevel(const LevelDef& level, const std::filesystem::path& path, const std::filesystem::path& schemaPath);

} // namespace abalike
