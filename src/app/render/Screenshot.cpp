#include "render/Screenshot.hpp"

#include <abalike/level/SafeText.hpp>

#include <SFML/Graphics/Image.hpp>
#include <SFML/Graphics/Texture.hpp>
#include <SFML/System/Err.hpp>
#include <iostream>

namespace abalike::app
{

bool saveScreenshot(const sf::RenderWindow& window, const std::string& path)
{
    // SFML explains its own failures on sf::err(); we say it once, in our words.
    std::streambuf* const sfmlErrors = sf::err().rdbuf(nullptr);
    sf::Texture texture;
    bool saved = texture.create(window.getSize().x, window.getSize().y);
    if (saved)
    {
        texture.update(window);
        saved = texture.copyToImage().saveToFile(path);
    }
    sf::err().rdbuf(sfmlErrors);
    if (!saved)
        std::cerr << "abalike: cannot save the screenshot to " << escapeForTerminal(path) << "\n";
    return saved;
}

} // namespace abalike::app
