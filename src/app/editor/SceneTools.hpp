#pragma once

#include <SFML/System/Vector2.hpp>
#include <SFML/Window/Event.hpp>
#include <abalike/edit/SceneEditor.hpp>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace abalike::app
{

struct EditorContext;
class PlayTest;

/// The mouse on the scene: the tool in hand (select, or a block, pig, terrain piece or slingshot to place), the
/// drag of a selection, a selection rectangle, panning, resize handles and a terrain polygon's corners.
class SceneTools
{
public:
    /// What a left click on the scene does.
    enum class Tool
    {
        Select,
        Block,
        Pig,
        Terrain,
        Slingshot,
        Drop, ///< the held bodies (Insert > a prefab, Generate here) drop where the click is
    };

    /// Bodies waiting for a click on the scene: they follow the pointer as an outline, and a click drops them there
    /// onto the surface below as one undo step (the menu that made them is where the pointer was).
    struct HeldBodies
    {
        LevelDef bodies;
        std::string label; ///< the undo step's name ("Insert pyramid", "Generate towers")
    };

    /// A corner of the one selected terrain polygon (or the middle of an edge, which adds a corner) under a pixel.
    struct VertexHandle
    {
        std::size_t terrain = 0;
        std::size_t vertex = 0; ///< the corner, or the edge from this corner to the next
        bool edgeMiddle = false;
    };

    explicit SceneTools(EditorContext& context) : m_ctx(context) {}

    /// A mouse event the panels did not take; while the scene plays it goes to the play test.
    void handleMouse(const sf::Event& event, PlayTest& play);
    /// Back to selecting, as after opening a scene.
    void reset()
    {
        tool = Tool::Select;
        held.reset();
    }
    /// The terrain tool with a polygon hill (six corners; its corners then edited on the scene).
    void chooseHill();
    /// The terrain tool with a 4 x 1 m box.
    void chooseTerrainBox();
    /// The drop tool with these bodies in hand.
    void hold(LevelDef bodies, std::string label);

    /// The object the current tool would place with its centre at a world point.
    ObjectDef toolObject(sf::Vector2f world) const;
    /// The selected polygon's corner and edge handles (none unless one polygon is selected with the select tool).
    std::vector<VertexHandle> vertexHandles() const;
    sf::Vector2f vertexHandlePosition(const VertexHandle& handle) const; ///< world
    /// True while a handle is being dragged (a resize or a corner).
    bool handleDragged() const { return m_resizing || m_vertexDrag; }
    /// Where pasted or inserted bodies go: under the pointer when it is on the scene, else the view's centre on the
    /// ground.
    Vec2 insertionPoint() const;

    Tool tool = Tool::Select;
    BlockDef blockTemplate{BlockShape::Box, "wood", 0.0, 0.0, 1.0, 1.0, 0.0, 0.1};
    PigDef pigTemplate{"small", 0.0, 0.0};
    TerrainDef terrainTemplate{0.0, 0.0, 4.0, 1.0, 0.0, {}};
    std::optional<HeldBodies> held; ///< what the drop tool holds
    sf::Vector2f pointer;           ///< the pointer's last pixel
    bool pointerOnScene = false;
    std::optional<sf::Vector2f> bandFrom; ///< a selection rectangle's first corner (world)

private:
    void pressOnScene(sf::Vector2f pixel, bool shift, bool ctrl);
    void dropHeld(sf::Vector2f world, bool shift);
    void moveOnScene(sf::Vector2f pixel);
    void releaseOnScene(sf::Vector2f pixel);
    std::optional<ObjectRef> resizeHandleAt(sf::Vector2f pixel) const;
    std::optional<VertexHandle> vertexHandleAt(sf::Vector2f pixel) const;
    void pressVertexHandle(const VertexHandle& handle, bool ctrl);

    EditorContext& m_ctx;
    std::optional<sf::Vector2f> m_dragFrom; ///< where a drag of the selection started (world)
    bool m_bandAdds = false;
    std::optional<sf::Vector2f> m_panFrom;    ///< panning with the right or middle button (pixels)
    std::optional<ObjectRef> m_resizing;      ///< a block or terrain piece being resized by its handle
    std::optional<VertexHandle> m_vertexDrag; ///< a terrain polygon's corner being dragged
};

} // namespace abalike::app
