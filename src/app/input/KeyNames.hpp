#pragma once

#include <SFML/Window/Keyboard.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace abalike::app
{

/// The key's name as SFML 2.5 spells its enumerator ("Escape", "Space", "F1", "Add", "Num1", "A"); empty for
/// sf::Keyboard::Unknown. Used by scripts (`--script`), the help overlay and the README's key table.
std::string keyName(sf::Keyboard::Key key);

/// The key with that name, if SFML has one.
std::optional<sf::Keyboard::Key> keyFromName(std::string_view name);

/// Every key name, in SFML's enumeration order.
const std::vector<std::string>& allKeyNames();

} // namespace abalike::app
