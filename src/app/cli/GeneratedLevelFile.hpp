#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace abalike::app
{

/// A generated level by its seed and loss share, as `play --generated SEED[:L]` names it ("4711" or "4711:0.3"; the
/// loss share defaults to 0.5). Throws UsageError for other text.
struct GeneratedLevelName
{
    std::uint64_t seed = 1;
    double lossShare = 0.5;
};
GeneratedLevelName parseGeneratedLevelName(const std::string& text);

/// The file of that level: the endless mode's shipped one (levels/endless/SEED-L.json), else the one in the cache
/// folder (generated/SEED-L.json, where the endless mode also keeps what it generates), generated and verified
/// first when it is not there yet (abalike generate's rules; about half a minute, said on stderr). The same name always
/// gives the same level. Throws UsageError when no level passes for that seed.
std::filesystem::path generatedLevelFile(const GeneratedLevelName& name);

} // namespace abalike::app
