#pragma once

#include <abalike/level/LevelDef.hpp>

#include <compare>
#include <cstddef>
#include <optional>
#include <string>
#include <variant>

namespace abalike
{

/// The kinds of object a scene holds. The slingshot is one object; the others are lists.
enum class ObjectKind
{
    Block,
    Pig,
    Terrain,
    Slingshot,
};

/// Names one object of a level: its kind and its index in the level's list of that kind (0 for the slingshot).
struct ObjectRef
{
    ObjectKind kind = ObjectKind::Block;
    std::size_t index = 0;

    auto operator<=>(const ObjectRef&) const = default;
};

/// An object's definition, whatever its kind.
using ObjectDef = std::variant<BlockDef, PigDef, TerrainDef, SlingshotDef>;

/// The JSON pointer of an object in the level file: "/blocks/3", "/pigs/0", "/terrain/1", "/slingshot".
std::string pointerOf(const ObjectRef& ref);

/// The object a JSON pointer (or one inside it, e.g. "/blocks/3/material") names; none for other pointers.
std::optional<ObjectRef> objectOfPointer(const std::string& pointer);

/// The kind of object a definition is.
ObjectKind kindOf(const ObjectDef& def);

/// True when the level has that object.
bool exists(const LevelDef& level, const ObjectRef& ref);

/// A copy of the object's definition. The reference must exist.
ObjectDef objectDef(const LevelDef& level, const ObjectRef& ref);

/// Replaces the object's definition; the kinds must match. The reference must exist.
void setObjectDef(LevelDef& level, const ObjectRef& ref, const ObjectDef& def);

/// Centre of an object (m): a body's centre, the slingshot's launch point.
Vec2 centreOf(const ObjectDef& def);

/// The same object moved so its centre is at (x, y).
ObjectDef withCentre(ObjectDef def, double x, double y);

/// Rotation (degrees); 0 for pigs and the slingshot, which do not turn.
double angleOf(const ObjectDef& def);

/// A short description for labels and findings: "block 3 (wood box)", "pig 0 (small)", "terrain 1", "slingshot".
std::string describe(const LevelDef& level, const ObjectRef& ref);

} // namespace abalike
