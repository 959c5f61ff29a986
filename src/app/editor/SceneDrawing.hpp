#pragma once

#include "render/Mesh.hpp"
#include "render/WorldRenderer.hpp"

#include <SFML/Graphics/RenderTarget.hpp>
#include <abalike/edit/SceneEditor.hpp>
#include <abalike/game/GameSession.hpp>
#include <cstdint>
#include <memory>
#include <string>

namespace abalike::app
{

class Camera;
struct EditorContext;
class SceneTools;

/// The scene as the game would build it, drawn as the game draws it, with the editor's marks over it: the grid, the
/// selection and its handles, findings in red, the current tool's ghost and the selection rectangle.
class SceneDrawing
{
public:
    SceneDrawing(EditorContext& context, const SceneTools& tools) : m_ctx(context), m_tools(tools) {}

    /// Builds the scene anew when it changed since the last frame.
    void refresh();
    void draw(sf::RenderTarget& target);

    /// The scene as built (null until the first refresh, or when it could not be built).
    const GameSession* session() const { return m_session.get(); }
    /// Why the scene could not be built; empty when it could.
    const std::string& error() const { return m_error; }

private:
    void drawOverlay(sf::RenderTarget& target);
    void drawGrid(const Camera& camera);
    void addOutline(const Camera& camera, const ObjectRef& ref, float widthPx, sf::Color colour);
    /// The drop tool's bodies as outlines, their bottom centre at the pointer (never below the ground).
    void addHeldOutline(const Camera& camera, sf::Vector2f pointer, float widthPx);

    EditorContext& m_ctx;
    const SceneTools& m_tools;
    std::unique_ptr<GameSession> m_session;
    std::uint64_t m_generation = ~0ull;
    std::uint64_t m_revision = ~0ull;
    std::string m_error;
    WorldRenderer m_renderer;
    Mesh m_mesh;
};

} // namespace abalike::app
