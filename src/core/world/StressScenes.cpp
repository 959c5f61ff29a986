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

} // namespace abalike
