#pragma once

#include <string>

namespace abalike::app
{

/// The bundled levels folder: $ABALIKE_LEVELS_DIR, else levels/ next to the source tree the binary was built from.
std::string levelsDirectory();

/// The bundled campaign manifest (levels/campaign.json).
std::string campaignManifest();

} // namespace abalike::app
