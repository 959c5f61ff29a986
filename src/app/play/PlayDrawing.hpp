#pragma once

#include "play/PlayLayer.hpp"
#include "render/Hud.hpp"
#include "render/OverlayRenderer.hpp"
#include "render/WorldRenderer.hpp"

#include <SFML/Graphics/RenderTarget.hpp>
#include <memory>
#include <vector>

namespace abalike::app
{

/// Draws a session the way the play screen does, for it and for the editor's play mode: the scenery, the last shot's
/// paths (faded while the next bird is aimed), the bodies with the loaded bird pulled back by `pullOffset`, the
/// contact markers, the preview, the layers' world drawing, the HUD and the layers' screen drawing. While a bird is
/// aimed the pull limit is drawn around the pouch, brighter while `pulling` (the mouse holds the bird).
void drawPlay(sf::RenderTarget& target, PlayView& view, WorldRenderer& world, OverlayRenderer& overlay, const Hud& hud,
              sf::Vector2f pullOffset, bool pulling, const std::vector<std::unique_ptr<PlayLayer>>& layers);

/// Launches a requested shot; a launch the rules refuse is told to the player. Returns true when it flew.
bool launchRequested(AppContext& app, GameSession& session, const ScriptedShot& shot);

} // namespace abalike::app
