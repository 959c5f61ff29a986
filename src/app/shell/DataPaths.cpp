#include "shell/DataPaths.hpp"

#include <abalike/world/SettleCache.hpp>

#include <cstdlib>
#include <filesystem>

namespace abalike::app
{

namespace
{

namespace fs = std::filesystem;

std::string environment(const char* name)
{
    const char* value = std::getenv(name);
    return value == nullptr ? std::string() : std::string(value);
}

bool hasCampaign(const fs::path& folder)
{
    std::error_code ec;
    return fs::is_regular_file(folder / "levels" / "campaign.json", ec);
}

} // namespace

std::string gameDataDirectory()
{
    if (std::string chosen = environment("ABALIKE_SHARE_DIR"); !chosen.empty())
        return chosen;
    // Relative to the executable, so a prefix can be moved and a build tree works without the source tree. The
    // paths come from the install layout (cmake/Install.cmake).
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    const fs::path installed = (exe.parent_path() / ABALIKE_DATA_FROM_INSTALLED_EXE).lexically_normal();
    const fs::path staged = (exe.parent_path() / ABALIKE_DATA_FROM_BUILD_EXE).lexically_normal();
    if (!ec)
        for (const fs::path& candidate : {installed, staged})
            if (hasCampaign(candidate))
                return candidate.string();
    // Neither has it: the installed place is where it should be, and reading the campaign there fails with a
    // message naming it. Not an error here, so a designer can still play a level file given by path.
    return installed.string();
}

std::string levelsDirectory()
{
    if (std::string chosen = environment("ABALIKE_LEVELS_DIR"); !chosen.empty())
        return chosen;
    return (fs::path(gameDataDirectory()) / "levels").string();
}

std::string campaignManifest()
{
    return (fs::path(levelsDirectory()) / "campaign.json").string();
}

void keepSettledLevelsIn(const std::string& dir)
{
    if (dir.empty())
        return;
    // A rebuilt program may solve the same level differently: its files must not be taken for this one's.
    std::error_code ec;
    const auto size = fs::file_size("/proc/self/exe", ec);
    const auto written = fs::last_write_time("/proc/self/exe", ec);
    if (ec)
        return;
    SettleCache::shared().setDirectory(dir, "abalike " + std::to_string(size) + " " +
                                                std::to_string(written.time_since_epoch().count()));
}

} // namespace abalike::app
