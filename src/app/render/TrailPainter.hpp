#pragma once

#include "render/Camera.hpp"
#include "render/ShotTrails.hpp"

#include <SFML/Graphics/RenderTarget.hpp>

namespace abalike::app
{

/// Draws the earlier shots' paths as a dimmed trail of puffs, as in the original game: a puff every 0.05 s of flight,
/// every fourth one larger, the older paths fainter. The current shot is not among them: the play screen draws it.
void drawShotTrails(sf::RenderTarget& target, const Camera& camera, const ShotTrails& trails, float uiScale);

} // namespace abalike::app
