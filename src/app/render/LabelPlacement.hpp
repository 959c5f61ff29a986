#pragma once

#include "render/ScreenRegions.hpp"

#include "render/Camera.hpp"

#include <SFML/Graphics/Rect.hpp>
#include <SFML/System/Vector2.hpp>
#include <abalike/game/GameSession.hpp>
#include <span>
#include <vector>

namespace abalike::app
{

/// Where each standing block and pig, the slingshot with its bird and the bird in flight are on screen (window
/// pixels): what labels and cards should not cover.
std::vector<sf::FloatRect> structureScreenBoxes(const GameSession& session, const Camera& camera);

/// What the panels over the world should leave visible, in window pixels: the slingshot with the bird it holds
/// ("slingshot"), the bird in flight ("bird") and every live pig ("pig").
std::vector<ScreenRegion> keepVisibleBoxes(const GameSession& session, const Camera& camera);

/// How much of a rectangle the boxes cover (pixels², overlaps counted once per box).
float coveredArea(const sf::FloatRect& rect, std::span<const sf::FloatRect> boxes);

/// The top-left corner for a label of this size next to an anchor point: the first of the spots around the anchor
/// (above right, above left, right, left, higher up, below) that lies inside the window and covers none of the
/// boxes; if every spot covers some, the one covering least. gap is the distance kept from the anchor.
sf::Vector2f placeLabel(sf::Vector2f anchor, sf::Vector2f size, sf::Vector2f window,
                        std::span<const sf::FloatRect> avoid, float gap);

} // namespace abalike::app
