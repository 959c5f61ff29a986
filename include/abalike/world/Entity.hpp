#pragma once

#include <abalike/level/LevelDef.hpp>
#include <string>

class b2Body;

namespace abalike
{
class Ability;
}

namespace abalike
{

enum class EntityKind
{
    Ground,
    Terrain,
    Block,
    Pig,
    Bird, ///< the launched bird and what its ability adds (split birds, eggs)
};

/// A body of the level as its files name it: its kind and its index in the level's blocks, pigs or terrain (-1 for
/// the ground; for a bird, its shot number).
struct BodyRef
{
    EntityKind kind = EntityKind::Ground;
    int index = -1;

    bool operator==(const BodyRef&) const = default;
};

/// The name of a kind in simulate's JSON and reports ("ground", "terrain", "block", "pig", "bird").
const char* entityKindName(EntityKind kind);

/// What broke a block or defeated a pig: the body that delivered the largest impulse in the step in which its
/// health reached zero, or the event that removed it.
enum class CauseKind
{
    Bird,        ///< the shot's bird or one of its split birds
    Block,       ///< a block (falling, sliding, thrown)
    Pig,         ///< a pig
    Explosion,   ///< the black bird's blast or a TNT crate's
    Ability,     ///< a body an ability added that is not one of the shot's birds (the egg): DefeatCause::ability
    Ground,      ///< the ground or terrain
    OutOfBounds, ///< it left the level's bounds
};

/// The name of a kind of cause ("bird", "block", ... "out_of_bounds"; "ability" for CauseKind::Ability).
const char* causeKindName(CauseKind kind);

struct DefeatCause
{
    CauseKind kind = CauseKind::Bird;
    int index = -1;                   ///< for Block and Pig: its index in the level's blocks or pigs; -1 otherwise
    const Ability* ability = nullptr; ///< for Ability: the ability that added the body
};

/// The name a cause has in simulate's JSON and play's trace: its kind's, or for a body an ability added the
/// ability's name ("egg").
std::string causeName(const DefeatCause& cause);

/// Something in the world the game cares about. Bodies point back at their entity by index (user data).
struct Entity
{
    EntityKind kind = EntityKind::Block;
    int defIndex = -1;    ///< index in the level's blocks / pigs / terrain, or the shot number for birds
    std::string typeName; ///< material, pig type or bird type
    BlockShape shape = BlockShape::Box;
    double widthM = 0.0; ///< blocks and terrain: size; pigs and birds: diameter
    double heightM = 0.0;
    double wallM = 0.0;  ///< hollow boxes: wall thickness
    double health = 0.0; ///< remaining impulse it can absorb (N s)
    double maxHealth = 0.0;
    bool alive = true;
    /// Birds only: one of the shot's birds (the bird, split birds), which count as the bird when they break
    /// something and start the shot's contact clock; false for a payload (an egg), which counts as its ability.
    bool shotBird = true;
    /// Birds an ability added (split birds, eggs): that ability; null for everything else.
    const Ability* madeBy = nullptr;
    b2Body* body = nullptr; ///< null once removed; built anew by the first step (GameWorld::box2d)
};

/// Something that was destroyed or left the world during the last steps, for score, effects and the defeat record.
/// Birds that retire after their shot appear too (kind Bird, 0 points): the game shows a puff there.
struct DestroyedEvent
{
    EntityKind kind = EntityKind::Block;
    std::string typeName;
    double x = 0.0;
    double y = 0.0;
    int points = 0;
    int index = -1;   ///< blocks and pigs: index in the level's blocks or pigs
    double timeS = 0; ///< world time (s since the level started)
    DefeatCause cause;
    int shot = -1; ///< the shot under way (from 0; -1 before the first launch); set by GameSession
};

/// A TNT crate that exploded: where and when, and what its blast pushed.
struct BlastEvent
{
    double timeS = 0.0;
    double x = 0.0;
    double y = 0.0;
    double radiusM = 0.0;
    int blockIndex = -1; ///< the crate's index in the level's blocks
};

} // namespace abalike
