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

/// The scenes that must stand still for 30 s (tests/world/StressSceneTest.cpp).
std::vector<StressScene> stressScenes();

} // namespace abalike
