#include "cli/DataPaths.hpp"

#include <cstdlib>
#include <filesystem>

namespace abalike::app
{

std::string levelsDirectory()
{
    if (const char* env = std::getenv("ABALIKE_LEVELS_DIR"); env != nullptr && *env != '\0')
        return env;
    // Installed layout first (bin/../share/abalike/levels), then the source tree of this build.
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec)
    {
        const auto installed = exe.parent_path().parent_path() / "share" / "abalike" / "levels";
        if (std::filesystem::is_directory(installed, ec))
            return installed.string();
    }
    return std::string(ABALIKE_SOURCE_DIR) + "/levels";
}

std::string campaignManifest()
{
    return levelsDirectory() + "/campaign.json";
}

} // namespace abalike::app
