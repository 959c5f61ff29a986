#include <abalike/edit/SceneObject.hpp>
#include <abalike/level/LevelWriter.hpp>

#include <algorithm>

#include <charconv>
#include <stdexcept>

namespace abalike
{

namespace
{

const char* listName(ObjectKind kind)
{
    switch (kind)
    {
    case ObjectKind::Block:
        return "blocks";
    case ObjectKind::Pig:
        return "pigs";
    case ObjectKind::Terrain:
        return "terrain";
    case ObjectKind::Slingshot:
        break;
    }
    return "slingshot";
}

} // namespace

std::string pointerOf(const ObjectRef& ref)
{
    if (ref.kind == ObjectKind::Slingshot)
        return "/slingshot";
    return std::string("/") + listName(ref.kind) + "/" + std::to_string(ref.index);
}

std::optional<ObjectRef> objectOfPointer(const std::string& pointer)
{
    if (pointer == "/slingshot" || pointer.rfind("/slingshot/", 0) == 0)
        return ObjectRef{ObjectKind::Slingshot, 0};
    for (const ObjectKind kind : {ObjectKind::Block, ObjectKind::Pig, ObjectKind::Terrain})
    {
        const std::string prefix = std::string("/") + listName(kind) + "/";
        if (pointer.rfind(prefix, 0) != 0)
            continue;
        const char* begin = pointer.data() + prefix.size();
        const char* end = pointer.data() + pointer.size();
        std::size_t index = 0;
        const auto [next, error] = std::from_chars(begin, end, index);
        if (error != std::errc() || next == begin || (next != end && *next != '/'))
            return std::nullopt;
        return ObjectRef{kind, index};
    }
    return std::nullopt;
}

ObjectKind kindOf(const ObjectDef& def)
{
    return static_cast<ObjectKind>(def.index());
}

bool exists(const LevelDef& level, const ObjectRef& ref)
{
    switch (ref.kind)
    {
    case ObjectKind::Block:
        return ref.index < level.blocks.size();
    case ObjectKind::Pig:
        return ref.index < level.pigs.size();
    case ObjectKind::Terrain:
        return ref.index < level.terrain.size();
    case ObjectKind::Slingshot:
        return ref.index == 0;
    }
    return false;
}

ObjectDef objectDef(const LevelDef& level, const ObjectRef& ref)
{
    switch (ref.kind)
    {
    case ObjectKind::Block:
        return level.blocks.at(ref.index);
    case ObjectKind::Pig:
        return level.pigs.at(ref.index);
    case ObjectKind::Terrain:
        return level.terrain.at(ref.index);
    case ObjectKind::Slingshot:
        break;
    }
    return level.slingshot;
}

void setObjectDef(LevelDef& level, const ObjectRef& ref, const ObjectDef& def)
{
    if (kindOf(def) != ref.kind)
        throw std::invalid_argument("setObjectDef: " + pointerOf(ref) + " cannot hold another kind of object");
    switch (ref.kind)
    {
    case ObjectKind::Block:
        level.blocks.at(ref.index) = std::get<BlockDef>(def);
        break;
    case ObjectKind::Pig:
        level.pigs.at(ref.index) = std::get<PigDef>(def);
        break;
    case ObjectKind::Terrain:
        level.terrain.at(ref.index) = std::get<TerrainDef>(def);
        break;
    case ObjectKind::Slingshot:
        level.slingshot = std::get<SlingshotDef>(def);
        break;
    }
}

Vec2 centreOf(const ObjectDef& def)
{
    return std::visit([](const auto& d) { return Vec2{d.x, d.y}; }, def);
}

ObjectDef withCentre(ObjectDef def, double x, double y)
{
    // A terrain polygon moves with its bounding box's centre: every point by the same step.
    if (auto* terrain = std::get_if<TerrainDef>(&def); terrain != nullptr && terrain->isPolygon())
        for (auto& point : terrain->points)
        {
            point.x += x - terrain->x;
            point.y += y - terrain->y;
        }
    std::visit(
        [&](auto& d)
        {
            d.x = x;
            d.y = y;
        },
        def);
    return def;
}

double angleOf(const ObjectDef& def)
{
    if (const auto* block = std::get_if<BlockDef>(&def))
        return block->angleDeg;
    if (const auto* terrain = std::get_if<TerrainDef>(&def))
        return terrain->angleDeg;
    return 0.0;
}

std::string describe(const LevelDef& level, const ObjectRef& ref)
{
    if (!exists(level, ref))
        return pointerOf(ref);
    switch (ref.kind)
    {
    case ObjectKind::Block:
    {
        const BlockDef& b = level.blocks[ref.index];
        std::string shape = blockShapeName(b.shape);
        std::replace(shape.begin(), shape.end(), '_', ' ');
        return "block " + std::to_string(ref.index) + " (" + b.material + " " + shape + ")";
    }
    case ObjectKind::Pig:
        return "pig " + std::to_string(ref.index) + " (" + level.pigs[ref.index].type + ")";
    case ObjectKind::Terrain:
        return "terrain " + std::to_string(ref.index);
    case ObjectKind::Slingshot:
        break;
    }
    return "slingshot";
}

} // namespace abalike
