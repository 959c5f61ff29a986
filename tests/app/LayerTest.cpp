// The app's folders form layers: a file may include a header of its own folder or of a folder on a lower layer,
// never one on its own layer or above (docs/extending.md, "Where things live"). The core/app boundary is kept by the
// build (CMakeLists.txt); this keeps the app's folders from growing circles again.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <regex>
#include <string>
#include <vector>

namespace
{

namespace fs = std::filesystem;

/// Each folder of src/app and its layer, lowest first.
const std::map<std::string, int> kLayers{
    {"plot", 0},   {"imgui", 0},   {"render", 1}, {"ui", 2},    {"input", 2},     {"endless", 2},
    {"shell", 3},  {"play", 4},    {"fx", 5},     {"audio", 5}, {"teach", 5},     {"layers", 6},
    {"editor", 7}, {"screens", 8}, {"bench", 9},  {"cli", 10},  {"main.cpp", 11},
};

/// The folder a path under src/app belongs to ("main.cpp" for the file at its root).
std::string folderOf(const fs::path& relative)
{
    return relative.begin()->string();
}

struct Include
{
    std::string file;
    int line = 0;
    std::string target;
};

std::vector<Include> appIncludes(const fs::path& root)
{
    // Quoted includes of the app's own headers: "folder/Name.hpp".
    const std::regex include(R"re(^\s*#\s*include\s+"([a-z]+)/[^"]+")re");
    std::vector<Include> found;
    for (const auto& entry : fs::recursive_directory_iterator(root))
    {
        const fs::path path = entry.path();
        if (!entry.is_regular_file() || (path.extension() != ".cpp" && path.extension() != ".hpp"))
            continue;
        std::ifstream in(path);
        std::string text;
        for (int line = 1; std::getline(in, text); ++line)
            if (std::smatch match; std::regex_search(text, match, include))
                found.push_back({fs::relative(path, root).string(), line, match[1]});
    }
    return found;
}

TEST(Layers, EveryFolderOfTheAppHasALayer)
{
    const fs::path root = fs::path(ABALIKE_SOURCE_DIR) / "src" / "app";
    for (const auto& entry : fs::directory_iterator(root))
    {
        const std::string name = entry.path().filename().string();
        if (entry.is_directory() || entry.path().extension() == ".cpp")
        {
            EXPECT_TRUE(kLayers.count(name) == 1)
                << "src/app/" << name << " has no layer: add it to kLayers here and to docs/extending.md";
        }
    }
}

TEST(Layers, NoIncludeGoesSidewaysOrUp)
{
    const fs::path root = fs::path(ABALIKE_SOURCE_DIR) / "src" / "app";
    const std::vector<Include> includes = appIncludes(root);
    ASSERT_GT(includes.size(), 500u) << "the scan found too few includes to mean anything";
    int checked = 0;
    for (const Include& include : includes)
    {
        const std::string from = folderOf(include.file);
        if (from == include.target)
            continue;
        const auto fromLayer = kLayers.find(from);
        const auto toLayer = kLayers.find(include.target);
        if (fromLayer == kLayers.end() || toLayer == kLayers.end())
            continue; // EveryFolderOfTheAppHasALayer names it
        ++checked;
        EXPECT_LT(toLayer->second, fromLayer->second)
            << "src/app/" << include.file << ":" << include.line << " includes " << include.target << "/ (layer "
            << toLayer->second << ") from " << from << "/ (layer " << fromLayer->second
            << "): a file may include only its own folder and folders on lower layers";
    }
    EXPECT_GT(checked, 200);
}

TEST(Layers, TheCheckCatchesAnIncludeAgainstTheLayers)
{
    // The same rule on a made-up include: render (1) may not include screens (8).
    const auto allowed = [](const std::string& from, const std::string& to)
    {
        return from == to || kLayers.at(to) < kLayers.at(from);
    };
    EXPECT_FALSE(allowed("render", "screens"));
    EXPECT_FALSE(allowed("teach", "fx")); // same layer: no sideways includes
    EXPECT_TRUE(allowed("screens", "render"));
}

} // namespace
