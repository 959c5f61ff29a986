#pragma once

#include <abalike/flight/FlightModel.hpp>
#include <abalike/world/Entity.hpp>
#include <functional>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace abalike
{

struct BirdType;

/// One impulse an ability applied, or the momentum it gave a body it created, for the teaching overlay.
struct AbilityImpulse
{
    double tS = 0.0; ///< time since launch
    double x = 0.0;  ///< where it acts (m)
    double y = 0.0;
    double impulseX = 0.0; ///< N s
    double impulseY = 0.0;
    std::string target; ///< "bird", "split bird", "egg", "block" or "pig"
};

/// What using a bird's ability did.
struct AbilityUse
{
    std::string ability; ///< the ability's name in the catalog ("split", "boost", "explode", "egg", ...)
    double tS = 0.0;     ///< time since launch
    double x = 0.0;      ///< where the bird was
    double y = 0.0;
    bool beforeContact = false; ///< used before the bird's first contact
    /// The launched bird's own flight changed before its first contact (boost, egg, explode; not split), so its
    /// first contact can no longer be compared with the prediction made at launch.
    bool changedFlight = false;
    /// How far from (x, y) the ability reached (a blast's radius; 0 when it acted on the bird alone).
    double reachM = 0.0;
    std::vector<AbilityImpulse> impulses;
    bool byFuse = false; ///< it went off by itself (Ability::fuseS), the player never used it
};

/// When a bird's ability can be used (once per bird).
enum class AbilityWindow
{
    FreeFlight, ///< before the bird's first contact
    InWorld,    ///< as long as the bird is in the world
};

/// What an ability drops: it leaves below the bird speedMps faster downwards than the bird.
struct DroppedPayload
{
    double speedMps = 0.0;
    double radiusM = 0.0;
};

/// A body an ability adds to the world: a split bird, an egg. Box2D flies it with its flight model's drag.
struct ProjectileSpec
{
    std::string typeName; ///< what the renderer and the records call it (the bird's name, "egg")
    double radiusM = 0.0;
    double massKg = 0.0;
    FlightState state{};
    FlightModel model;
    /// One of the shot's birds (its first touch is the shot's contact); false: a payload, which counts as its
    /// ability when it breaks something.
    bool shotBird = true;
};

/// What an ability may do to the world while the launched bird is in it. GameWorld implements it.
class AbilityWorld
{
public:
    virtual ~AbilityWorld() = default;

    /// The launched bird's state now (x, y, vx, vy).
    virtual FlightState birdState() const = 0;
    virtual const BirdType& birdType() const = 0;
    /// The flight model the bird was launched with (drag, wind, gravity).
    virtual const FlightModel& birdModel() const = 0;
    /// Air density of the level's environment (kg/m^3).
    virtual double airDensity() const = 0;
    /// Gives the bird a new velocity; in free flight it goes on along a new RK4 path from here.
    virtual void setBirdVelocity(double vx, double vy) = 0;
    virtual void addProjectile(const ProjectileSpec& projectile) = 0;
    /// A radial blast at (x, y): every block and pig whose centre is within radiusM gets impulseNs (1 - d / R),
    /// as push and as damage; crates it breaks explode in turn. Each push is appended to impulses.
    virtual void blast(double x, double y, double radiusM, double impulseNs, std::vector<AbilityImpulse>& impulses,
                       double tS) = 0;
    /// Takes the launched bird out of the world.
    virtual void removeBird() = 0;
};

/// A bird's ability: one rule of physics the player triggers once in flight. Each ability is one file under
/// src/core/world/abilities/ and one line of the table in AbilityTable.cpp; the catalog names it by its name and
/// gives its numbers in "abilities" (docs/extending.md).
class Ability
{
public:
    virtual ~Ability() = default;

    /// Its name in assets/catalog.json ("split", ...).
    virtual std::string_view name() const = 0;
    virtual AbilityWindow window() const = 0;
    /// Acts on the world and records what it did in use (impulses, changedFlight, reachM); use's name, time, place
    /// and beforeContact are already set.
    virtual void use(AbilityWorld& world, AbilityUse& use) const = 0;
    /// One of its numbers by its key in the catalog ("angle_deg", "impulse_ns", ...); throws std::out_of_range.
    virtual double number(std::string_view key) const = 0;
    /// Its numbers for the catalog's table ("10.0 deg").
    virtual std::string parameters() const = 0;
    /// What it does, one sentence for the catalog's table.
    virtual std::string_view description() const = 0;
    /// An ability that drops a payload (the egg) describes it, so the solver can time the drop over a target; none
    /// for every other ability.
    virtual std::optional<DroppedPayload> dropped() const { return std::nullopt; }
    /// An ability that goes off by itself if the player never uses it (the black bird's fuse, as in the genre): this
    /// long after the bird's first contact, or as the bird comes to rest, whichever is first. None: it waits.
    virtual std::optional<double> fuseS() const { return std::nullopt; }
};

/// Makes an ability from its block in the catalog's "abilities" (an empty object when the catalog has none: the
/// ability's own defaults). Throws std::runtime_error naming a bad number.
using AbilityFactory = std::function<std::shared_ptr<const Ability>(const nlohmann::json& params)>;

/// One line of the table of abilities: the name the catalog uses and the function that makes it.
struct AbilityTableEntry
{
    std::string_view name;
    std::shared_ptr<const Ability> (*make)(const nlohmann::json& params);
};

/// Every ability the program knows: an explicit table (src/core/world/abilities/AbilityTable.cpp), so linking the
/// core in any way keeps them all.
const std::vector<AbilityTableEntry>& abilityTable();

/// Every ability the program knows, by name, read from the table.
class AbilityRegistry
{
public:
    /// The factory of an ability, or null when no ability has that name.
    static const AbilityFactory* find(std::string_view name);
    /// Every known name, sorted.
    static std::vector<std::string> names();
};

/// The name the catalog uses for a bird without an ability.
inline constexpr std::string_view kNoAbility = "none";

} // namespace abalike
