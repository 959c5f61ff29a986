#include <abalike/world/StressScenes.hpp>

namespace abalike
{

namespace
{

/// A level with nothing but a slingshot, one bird and one pig on the ground, for scenes to fill.
LevelDef emptyScene(const std::string& id, const std::string& title)
{
    LevelDef level;
    level.id = id;
    level.title = title;
    level.birds = {"red"};
    level.pigs = {{"small", 40.0, 0.25}};
    return level;
}

BlockDef box(const std::string& material, double x, double y, double w, double h)
{
    BlockDef block;
    block.material = material;
    block.x = x;
    block.y = y;
    block.widthM = w;
    block.heightM = h;
    return block;
}

} // namespace

LevelDef towerScene(int blocks)
{
    LevelDef level =
        emptyScene("stress-tower-" + std::to_string(blocks), "Tower of " + std::to_string(blocks) + " blocks");
    constexpr double kSize = 0.5;
    for (int i = 0; i < blocks; ++i)
        level.blocks.push_back(box("wood", 20.0, kSize * (i + 0.5), kSize, kSize));
    return level;
}

LevelDef pyramidScene(int rows)
{
    LevelDef level =
        emptyScene("stress-pyramid-" + std::to_string(rows), "Pyramid of " + std::to_string(rows) + " rows");
    // Box2D's own pyramid benchmark leaves an eighth of a box between neighbours.
    constexpr double kSize = 0.5;
    constexpr double kPitch = 1.125 * kSize;
    const double left = 20.0;
    for (int row = 0; row < rows; ++row)
    {
        const int count = rows - row;
        const double x0 = left + row * kPitch / 2;
        for (int i = 0; i < count; ++i)
            level.blocks.push_back(box("wood", x0 + i * kPitch, kSize * (row + 0.5), kSize, kSize));
    }
    level.pigs = {{"small", left + rows * kPitch + 10.0, 0.25}};
    return level;
}

LevelDef stoneOnIceScene()
{
    LevelDef level = emptyScene("stress-stone-on-ice", "Stone blocks on ice planks");
    constexpr double kPlankW = 2.0;
    constexpr double kPlankH = 0.2;
    constexpr double kStone = 0.5;
    double y = 0.0;
    for (int storey = 0; storey < 3; ++storey)
    {
        level.blocks.push_back(box("ice", 20.0, y + kPlankH / 2, kPlankW, kPlankH));
        y += kPlankH;
        level.blocks.push_back(box("stone", 20.0 - 0.7, y + kStone / 2, kStone, kStone));
        level.blocks.push_back(box("stone", 20.0 + 0.7, y + kStone / 2, kStone, kStone));
        y += kStone;
    }
    level.blocks.push_back(box("ice", 20.0, y + kPlankH / 2, kPlankW, kPlankH));
    level.pigs.push_back({"small", 20.0, y + kPlankH + 0.25});
    return level;
}

LevelDef bridgeScene()
{
    LevelDef level = emptyScene("stress-bridge", "Wide bridge of planks on two columns");
    constexpr double kColumnW = 0.5;
    constexpr double kColumnH = 3.0;
    constexpr double kSpan = 9.0;
    constexpr double kPlankH = 0.25;
    const double left = 20.0;
    const double mid = left + kSpan / 2;
    level.blocks.push_back(box("wood", left, kColumnH / 2, kColumnW, kColumnH));
    level.blocks.push_back(box("wood", left + kSpan, kColumnH / 2, kColumnW, kColumnH));
    double y = kColumnH;
    for (int deck = 0; deck < 2; ++deck)
    {
        level.blocks.push_back(box("wood", mid, y + kPlankH / 2, kSpan + kColumnW, kPlankH));
        y += kPlankH;
    }
    for (const double dx : {-3.0, -1.0, 1.0, 3.0})
        level.blocks.push_back(box(dx == -1.0 || dx == 1.0 ? "ice" : "wood", mid + dx, y + 0.25, 0.5, 0.5));
    level.pigs.push_back({"medium", mid, y + 0.35});
    return level;
}

LevelDef shapesScene()
{
    LevelDef level = emptyScene("stress-shapes", "Every block shape at rest");
    // A hollow stone box with a pig inside, a wood triangle on a box, a circle on the ground, a hollow box on a
    // plank on two columns.
    BlockDef hollow = box("stone", 20.0, 0.6, 1.6, 1.2);
    hollow.shape = BlockShape::HollowBox;
    hollow.wallM = 0.15;
    level.blocks.push_back(hollow);
    level.pigs.push_back({"small", 20.0, 0.15 + 0.25});

    level.blocks.push_back(box("wood", 23.0, 0.5, 1.0, 1.0));
    BlockDef triangle = box("wood", 23.0, 1.5, 1.0, 1.0);
    triangle.shape = BlockShape::Triangle;
    level.blocks.push_back(triangle);

    BlockDef circle = box("ice", 25.5, 0.4, 0.8, 0.8);
    circle.shape = BlockShape::Circle;
    level.blocks.push_back(circle);

    level.blocks.push_back(box("wood", 27.5, 1.0, 0.25, 2.0));
    level.blocks.push_back(box("wood", 29.5, 1.0, 0.25, 2.0));
    level.blocks.push_back(box("wood", 28.5, 2.125, 2.6, 0.25));
    BlockDef frame = box("wood", 28.5, 2.75, 1.0, 1.0);
    frame.shape = BlockShape::HollowBox;
    frame.wallM = 0.1;
    level.blocks.push_back(frame);
    level.pigs.push_back({"small", 28.5, 2.35 + 0.25});
    return level;
}

LevelDef wallScene(const WallSpec& spec)
{
    const std::string size = std::to_string(spec.columns) + "x" + std::to_string(spec.rows);
    LevelDef level = emptyScene("stress-wall-" + size, "Wall of " + size + " bricks");
    const double left = 20.0;
    const double w = spec.brickWM;
    const double h = spec.brickHM;
    const auto material = [&](int column, int row)
    {
        return spec.materials[static_cast<std::size_t>(column + row) % spec.materials.size()];
    };
    for (int row = 0; row < spec.rows; ++row)
    {
        const double y = h * (row + 0.5);
        if (!spec.staggered || row % 2 == 0)
        {
            for (int c = 0; c < spec.columns; ++c)
                level.blocks.push_back(box(material(c, row), left + w * (c + 0.5), y, w, h));
            continue;
        }
        // A shifted row: a half brick at each end keeps the wall's ends straight. Half bricks are of the last
        // (densest) material, so that no full brick rests on a half brick more than ten times lighter.
        const std::string& half = spec.materials.back();
        level.blocks.push_back(box(half, left + w / 4, y, w / 2, h));
        for (int c = 1; c < spec.columns; ++c)
            level.blocks.push_back(box(material(c, row), left + w * c, y, w, h));
        level.blocks.push_back(box(half, left + w * spec.columns - w / 4, y, w / 2, h));
    }
    level.pigs = {{"small", left + w * spec.columns / 2, h * spec.rows + 0.25}};
    return level;
}

LevelDef storeyTowerScene(const TowerSpec& spec)
{
    LevelDef level = emptyScene("stress-tower-" + std::to_string(spec.storeys) + "-storeys",
                                "Tower of " + std::to_string(spec.storeys) + " storeys");
    constexpr double kColumnW = 0.3;
    constexpr double kColumnH = 1.5;
    constexpr double kPlankW = 2.6;
    constexpr double kPlankH = 0.25;
    const double centre = 20.0;
    double y = 0.0;
    for (int storey = 0; storey < spec.storeys; ++storey)
    {
        const auto k = static_cast<std::size_t>(storey);
        const std::string& column = spec.columnMaterials[k % spec.columnMaterials.size()];
        const std::string& plank = spec.plankMaterials[k % spec.plankMaterials.size()];
        for (const double side : {-1.0, 1.0})
            level.blocks.push_back(
                box(column, centre + side * (kPlankW - kColumnW) / 2, y + kColumnH / 2, kColumnW, kColumnH));
        y += kColumnH;
        level.blocks.push_back(box(plank, centre, y + kPlankH / 2, kPlankW, kPlankH));
        y += kPlankH;
    }
    level.pigs = {{"small", centre, y + 0.25}};
    return level;
}

LevelDef offCentreLoadScene(int bricks)
{
    WallSpec spec;
    spec.columns = 1;
    spec.rows = bricks;
    LevelDef level = wallScene(spec);
    level.id = "stress-off-centre-load";
    level.title = "Column of bricks with a stone block off-centre on top";
    constexpr double kStone = 0.25;
    level.blocks.push_back(box("stone", 20.25 + 0.1, 0.25 * bricks + kStone / 2, kStone, kStone));
    level.pigs = {{"small", 40.0, 0.25}};
    return level;
}

LevelDef ledgeScene()
{
    LevelDef level = emptyScene("stress-ledges", "Blocks packed side by side on terrain ledges");
    constexpr double kBrickW = 0.5;
    constexpr double kBrickH = 0.25;
    level.pigs.clear();
    // A 6 m ledge 3 m up, covered edge to edge by three rows of twelve bricks.
    level.terrain.push_back({30.0, 1.5, 6.0, 3.0, 0.0, {}});
    for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 12; ++c)
            level.blocks.push_back(box(row == 1 ? "ice" : "wood", 27.0 + kBrickW * (c + 0.5),
                                       3.0 + kBrickH * (row + 0.5), kBrickW, kBrickH));
    level.pigs.push_back({"small", 30.0, 3.0 + 3 * kBrickH + 0.25});
    // Ten blocks wedged between two terrain walls 5 m apart, two rows, the lower one of ice.
    level.terrain.push_back({39.5, 1.5, 1.0, 3.0, 0.0, {}});
    level.terrain.push_back({45.5, 1.5, 1.0, 3.0, 0.0, {}});
    for (int row = 0; row < 2; ++row)
        for (int c = 0; c < 10; ++c)
            level.blocks.push_back(
                box(row == 0 ? "ice" : "stone", 40.0 + kBrickW * (c + 0.5), kBrickH * (row + 0.5), kBrickW, kBrickH));
    level.pigs.push_back({"small", 42.5, 2 * kBrickH + 0.25});
    return level;
}

std::vector<StressScene> stressScenes()
{
    return {
        {"tower", "20 wood blocks in one column", towerScene(20)},
        {"pyramid", "15-row pyramid of 120 wood boxes", pyramidScene(15)},
        {"stone-on-ice", "stone blocks on ice planks, three storeys (mass ratio 3.75)", stoneOnIceScene()},
        {"bridge", "9.5 m double plank deck on two columns 9 m apart, loaded", bridgeScene()},
        {"shapes", "hollow boxes (one holding a pig), triangle, circle", shapesScene()},
    };
}

std::vector<StressScene> structureScenes()
{
    const std::vector<std::string> mixed{"wood", "ice", "stone"};
    const auto wall =
        [](int columns, int rows, double w, double h, std::vector<std::string> materials, bool staggered = false)
    {
        WallSpec spec;
        spec.columns = columns;
        spec.rows = rows;
        spec.brickWM = w;
        spec.brickHM = h;
        spec.materials = std::move(materials);
        spec.staggered = staggered;
        return wallScene(spec);
    };
    const auto tower = [](int storeys, std::vector<std::string> columns, std::vector<std::string> planks)
    {
        return storeyTowerScene({storeys, std::move(columns), std::move(planks)});
    };
    return {
        {"column-bricks", "20 wood bricks 0.5 x 0.25 m in one column", wall(1, 20, 0.5, 0.25, {"wood"})},
        {"column-long-bricks", "20 wood bricks 1.0 x 0.25 m in one column", wall(1, 20, 1.0, 0.25, {"wood"})},
        {"wall-5x5-small", "5 x 5 wall of 0.25 x 0.125 m wood bricks", wall(5, 5, 0.25, 0.125, {"wood"})},
        {"wall-10x10", "10 x 10 wall of 0.5 x 0.25 m wood bricks", wall(10, 10, 0.5, 0.25, {"wood"})},
        {"wall-10x20", "10 x 20 wall of 0.5 x 0.25 m wood bricks (5 x 5 m)", wall(10, 20, 0.5, 0.25, {"wood"})},
        {"wall-10x10-ice", "10 x 10 wall of 0.5 x 0.25 m ice bricks", wall(10, 10, 0.5, 0.25, {"ice"})},
        {"wall-20x10-large", "20 x 10 wall of 1.0 x 0.5 m wood blocks", wall(20, 10, 1.0, 0.5, {"wood"})},
        {"wall-20x10-staggered", "20 x 10 wall of 1.0 x 0.5 m wood blocks, every other row shifted half a block",
         wall(20, 10, 1.0, 0.5, {"wood"}, true)},
        {"wall-20x20-stone", "20 x 20 wall of 0.5 x 0.25 m stone bricks", wall(20, 20, 0.5, 0.25, {"stone"})},
        {"wall-5x10-mixed", "5 x 10 wall of 0.5 x 0.25 m bricks, wood, ice and stone in turn",
         wall(5, 10, 0.5, 0.25, mixed)},
        {"wall-20x20-small-staggered", "20 x 20 staggered wall of 0.25 x 0.125 m bricks, wood, ice and stone in turn",
         wall(20, 20, 0.25, 0.125, mixed, true)},
        {"wall-20x50-mixed", "20 x 50 wall of 0.5 x 0.25 m bricks, wood, ice and stone in turn (1 000 blocks)",
         wall(20, 50, 0.5, 0.25, mixed)},
        {"tower-8-mixed", "8 storeys, columns stone, wood, ice in turn, wood planks, pig on top",
         tower(8, {"stone", "wood", "ice"}, {"wood"})},
        {"tower-8-stone-planks", "8 storeys, columns stone and wood in turn under stone planks (mass ratio 6.9)",
         tower(8, {"stone", "wood"}, {"stone"})},
        {"tower-12-mixed", "12 storeys, columns stone, wood, ice in turn, planks wood and stone in turn",
         tower(12, {"stone", "wood", "ice"}, {"wood", "stone"})},
        {"tower-12-ice-stone", "12 storeys, columns ice and stone in turn under wood planks",
         tower(12, {"ice", "stone"}, {"wood"})},
        {"ledges", "bricks packed side by side on a terrain ledge and between two terrain walls", ledgeScene()},
        {"off-centre-load", "10 wood bricks in a column, a stone block 0.1 m off its axis on top",
         offCentreLoadScene(10)},
    };
}

} // namespace abalike
