#pragma once

#include <abalike/level/LevelDef.hpp>
#include <string>
#include <vector>

namespace abalike
{

/// A scene built to test what the world can hold up: defined once here and used by the tests (it must stand),
/// by `abalike bench perf` (it is timed) and by the game's debug screen (it is looked at).
struct StressScene
{
    std::string name;        ///< short id, e.g. "tower"
    std::string description; ///< one line for tables and the debug screen
    LevelDef level;
};

/// A single column of square wood blocks, 0.5 m each.
LevelDef towerScene(int blocks = 20);
/// A pyramid of 0.5 m wood boxes; rows * (rows + 1) / 2 boxes (40 rows: 820).
LevelDef pyramidScene(int rows = 15);
/// Stone blocks resting on ice planks, three storeys (stone is 3.75 times the mass of the plank under it).
LevelDef stoneOnIceScene();
/// A 9.5 m wood plank deck on two columns 9 m apart, a second deck on it and a load on top.
LevelDef bridgeScene();
/// Every block shape at rest: triangle, circle, hollow box (with a pig inside), boxes of several sizes.
LevelDef shapesScene();

/// A wall of bricks laid side by side, each resting exactly on the row below and touching its neighbours.
struct WallSpec
{
    int columns = 10;
    int rows = 10;
    double brickWM = 0.5;
    double brickHM = 0.25;
    /// Every other row shifted by half a brick, with half bricks at its two ends (a running bond).
    bool staggered = false;
    /// Materials cycled brick by brick along the diagonals ((column + row) mod n): one entry for a uniform wall.
    /// The half bricks of a staggered wall are of the last one: list the densest last.
    std::vector<std::string> materials{"wood"};
};

/// A wall built as the spec says, standing on the ground from x = 20 m, with a pig on top.
LevelDef wallScene(const WallSpec& spec);

/// A tower of storeys, each two 0.3 x 1.5 m columns under a 2.6 x 0.25 m plank, with a pig on top.
struct TowerSpec
{
    int storeys = 8;
    /// Column materials, cycled storey by storey (both columns of a storey are the same).
    std::vector<std::string> columnMaterials{"stone", "wood", "ice"};
    /// Plank materials, cycled storey by storey.
    std::vector<std::string> plankMaterials{"wood"};
};

/// A tower built as the spec says, on the ground at x = 20 m.
LevelDef storeyTowerScene(const TowerSpec& spec);

/// A column of 0.5 x 0.25 m wood bricks with a 0.25 m stone cube 0.1 m off its axis on top (2.4 times a brick):
/// the off-centre load a tall stack must hold without leaning.
LevelDef offCentreLoadScene(int bricks = 10);

/// Rows of blocks packed side by side on terrain ledges: a ledge at 3 m with a 3-row wall, and blocks wedged
/// between two terrain walls, each block touching its neighbours and the terrain.
LevelDef ledgeScene();

/// The scenes that must stand still for 30 s (tests/world/StressSceneTest.cpp).
std::vector<StressScene> stressScenes();

/// Walls, mixed-material towers and packed ledges (issue 9): structures of blocks in side contact that must stand
/// still for 30 s like the scenes above; the largest is the 1 000-block wall, the format's maximum.
std::vector<StressScene> structureScenes();

} // namespace abalike
