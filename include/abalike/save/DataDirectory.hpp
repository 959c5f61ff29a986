#pragma once

#include <filesystem>

namespace abalike
{

/// Where the player's files live: $ABALIKE_DATA_DIR, else $XDG_DATA_HOME/abalike, else ~/.local/share/abalike.
/// Empty when the environment names none of these.
std::filesystem::path defaultDataDirectory();

/// The same rule with the environment passed in (nullptr for an unset variable).
std::filesystem::path dataDirectoryFrom(const char* abalikeDataDir, const char* xdgDataHome, const char* home);

/// Where the game keeps what it can compute again (settled levels): $ABALIKE_DATA_DIR/cache, else
/// $XDG_CACHE_HOME/abalike, else ~/.cache/abalike. Empty when the environment names none of these.
std::filesystem::path defaultCacheDirectory();

/// The same rule with the environment passed in (nullptr for an unset variable).
std::filesystem::path cacheDirectoryFrom(const char* abalikeDataDir, const char* xdgCacheHome, const char* home);

} // namespace abalike
