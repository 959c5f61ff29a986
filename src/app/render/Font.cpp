#include "render/Font.hpp"

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>
#include <vector>

namespace abalike::app
{

namespace
{
/// The player's choice first, then the font found when the game was configured, then Debian's path.
std::vector<std::string> fontCandidates()
{
    std::vector<std::string> candidates;
    if (const char* fromEnvironment = std::getenv("ABALIKE_FONT"))
        candidates.emplace_back(fromEnvironment);
#ifdef ABALIKE_FONT_FILE
    candidates.emplace_back(ABALIKE_FONT_FILE);
#endif
    candidates.emplace_back("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf");
    return candidates;
}

bool isFile(const std::string& path)
{
    // Check first: SFML reports every failed load on stderr, and a missing candidate is not an error.
    std::error_code error;
    return !path.empty() && std::filesystem::is_regular_file(path, error);
}
} // namespace

std::unique_ptr<sf::Font> loadGameFont()
{
    for (const std::string& path : fontCandidates())
    {
        if (!isFile(path))
            continue;
        auto font = std::make_unique<sf::Font>();
        if (font->loadFromFile(path))
            return font;
    }
    std::cerr << "abalike: no font found (install fonts-dejavu-core or set ABALIKE_FONT); playing without text\n";
    return nullptr;
}

std::string gameFontPath()
{
    for (const std::string& path : fontCandidates())
        if (isFile(path))
            return path;
    return {};
}

} // namespace abalike::app
