#pragma once

#include <abalike/level/LevelIO.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace abalike
{

/// A scene the editor autosaved, and the level file it belongs to (empty for a scene never saved).
struct AutosavedScene
{
    LevelDef level;
    std::filesystem::path target;
    std::vector<LevelIssue> geometryIssues;
};

/// The autosave file in the player's data directory.
std::filesystem::path autosavePath(const std::filesystem::path& dataDirectory);

/// Writes the scene to the autosave file atomically (see writeFileAtomically): the level as it would be saved, and
/// its target file. A scene that could not be saved as a level because it has no pig is kept as a sandbox scene, so
/// it always opens again. Throws SaveIoError.
void writeAutosave(const std::filesystem::path& file, const LevelDef& level, const std::filesystem::path& target,
                   const Catalog& catalog);

/// The autosaved scene; none when there is no autosave file. Throws LevelLoadError when the file is damaged.
std::optional<AutosavedScene> readAutosave(const std::filesystem::path& file, const Catalog& catalog);

/// Deletes the autosave file (after a save, or when the user discards it); no error if it is not there.
void removeAutosave(const std::filesystem::path& file);

} // namespace abalike
