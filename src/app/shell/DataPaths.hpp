#pragma once

#include <string>

namespace abalike::app
{

/// The folder of the game's read-only data (levels/ with the campaign and its schema, assets/):
/// $ABALIKE_SHARE_DIR, else the installed tree beside the executable (PREFIX/games/abalike reads
/// PREFIX/share/games/abalike), else the copy a build stages beside its executable (build/share/games/abalike).
/// Never the source tree. When none has levels/campaign.json, the installed place (reading it then fails, naming it).
std::string gameDataDirectory();

/// The bundled levels folder: $ABALIKE_LEVELS_DIR, else levels/ in gameDataDirectory().
std::string levelsDirectory();

/// The bundled campaign manifest (levels/campaign.json).
std::string campaignManifest();

/// Keeps settled levels as files in dir (SettleCache), marked with this build of the program (the executable's size
/// and time), so the next start loads a big level without its settle step.
void keepSettledLevelsIn(const std::string& dir);

} // namespace abalike::app
