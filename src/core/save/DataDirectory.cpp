#include <abalike/save/DataDirectory.hpp>
#include <cstdlib>

namespace abalike
{

namespace
{

bool isSet(const char* value)
{
    return value != nullptr && *value != '\0';
}

} // namespace

std::filesystem::path dataDirectoryFrom(const char* abalikeDataDir, const char* xdgDataHome, const char* home)
{
    if (isSet(abalikeDataDir))
        return abalikeDataDir;
    // The XDG base directory spec says a relative XDG_DATA_HOME is invalid and must be ignored.
    if (isSet(xdgDataHome) && std::filesystem::path(xdgDataHome).is_absolute())
        return std::filesystem::path(xdgDataHome) / "abalike";
    if (isSet(home))
        return std::filesystem::path(home) / ".local" / "share" / "abalike";
    return {};
}

std::filesystem::path defaultDataDirectory()
{
    return dataDirectoryFrom(std::getenv("ABALIKE_DATA_DIR"), std::getenv("XDG_DATA_HOME"), std::getenv("HOME"));
}

std::filesystem::path cacheDirectoryFrom(const char* abalikeDataDir, const char* xdgCacheHome, const char* home)
{
    if (isSet(abalikeDataDir))
        return std::filesystem::path(abalikeDataDir) / "cache";
    if (isSet(xdgCacheHome) && std::filesystem::path(xdgCacheHome).is_absolute())
        return std::filesystem::path(xdgCacheHome) / "abalike";
    if (isSet(home))
        return std::filesystem::path(home) / ".cache" / "abalike";
    return {};
}

std::filesystem::path defaultCacheDirectory()
{
    return cacheDirectoryFrom(std::getenv("ABALIKE_DATA_DIR"), std::getenv("XDG_CACHE_HOME"), std::getenv("HOME"));
}

} // namespace abalike
