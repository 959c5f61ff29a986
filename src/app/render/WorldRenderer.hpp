#pragma once

#include <array>

#include "render/Camera.hpp"
#include "render/Mesh.hpp"

#include <SFML/Graphics/RenderTarget.hpp>
#include <abalike/game/GameSession.hpp>
#include <optional>
#include <vector>

namespace abalike::app
{

/// Draws the level as the world has it now: sky, ground, terrain, blocks, pigs, birds and the slingshot.
/// Reads positions from the Box2D bodies and draws every fixture in its true geometry.
class WorldRenderer
{
public:
    /// Where the bird in the slingshot is drawn for this pull (world metres): in the pouch moved by the pull, never
    /// below what the slingshot stands on. None while no bird is aimed.
    std::optional<sf::Vector2f> loadedBirdAt(const GameSession& session, sf::Vector2f pullOffset);
    /// The scenery: sky, ground and terrain. Shot paths go between this and the foreground.
    void drawBackground(sf::RenderTarget& target, const Camera& camera, const GameSession& session);
    /// Everything that moves or can be hit: slingshot and birds, blocks, pigs. pullOffset is where the loaded
    /// bird sits relative to the pouch while aiming (world metres).
    void drawForeground(sf::RenderTarget& target, const Camera& camera, const GameSession& session,
                        sf::Vector2f pullOffset);

private:
    void addTerrain(const Entity& entity, float pixelM);
    /// A terrain polygon: its convex pieces filled as one, its outline, grass on its top edges.
    void addTerrainPolygon(const Entity& entity, const TerrainDef& def, float pixelM);
    void addBlock(const Entity& entity, const Catalog& catalog, std::size_t index, float pixelM);
    void addPig(const Entity& entity, const Catalog& catalog, float pixelM);
    void addBird(const Entity& entity, const Catalog& catalog, std::size_t index, float pixelM);
    /// Remembers which birds have touched something (they look dazed from then on); forgets on a new world.
    void updateDazed(const GameSession& session);
    void addWaitingBirds(const GameSession& session, float pixelM);
    void addOffscreenMarker(const Entity& bird, const Catalog& catalog, const Camera& camera);

    Mesh m_base; ///< the backdrop's opaque fills, drawn without blending
    Mesh m_mesh;
    std::vector<bool> m_dazed; ///< by entity index
    const GameWorld* m_dazedWorld = nullptr;
    double m_dazedTimeS = 0.0;
    sf::Color m_surface = sf::Color(96, 178, 64); ///< the world's surface colour (grass on Earth), for terrain tops

    /// GameWorld::surfaceBelow, remembered: terrain and ground are static, so the slingshot's and the waiting birds'
    /// footing is ray cast once per level layout, not every frame.
    double standingY(const GameWorld& world, double x, double fromY);
    std::vector<TerrainDef> m_standTerrain;
    double m_standGroundY = 0.0;
    std::vector<std::array<double, 3>> m_standCache; ///< (x, fromY, surface y)
};

} // namespace abalike::app
