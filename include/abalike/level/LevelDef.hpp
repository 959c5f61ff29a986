#pragma once

#include <abalike/flight/FlightModel.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace abalike
{

/// Shapes a block can have.
enum class BlockShape
{
    Box,       ///< width x height rectangle (squares, planks, columns)
    Circle,    ///< diameter = width
    Triangle,  ///< right triangle with legs width and height
    HollowBox, ///< width x height frame of four walls wallM thick, one body ("hollow_box" in JSON)
};

/// A block of building material. Position is the centre of its bounding box (m), angle counter-clockwise.
struct BlockDef
{
    BlockShape shape = BlockShape::Box;
    std::string material = "wood";
    double x = 0.0;
    double y = 0.0;
    double widthM = 1.0;
    double heightM = 1.0;
    double angleDeg = 0.0;
    double wallM = 0.1; ///< HollowBox: wall thickness (m)

    bool operator==(const BlockDef&) const = default;
};

/// A pig; it rests on whatever is below its centre.
struct PigDef
{
    std::string type = "small";
    double x = 0.0;
    double y = 0.0;

    bool operator==(const PigDef&) const = default;
};

/// A static box of terrain (hills, platforms), centre and size in metres.
struct TerrainDef
{
    double x = 0.0;
    double y = 0.0;
    double widthM = 1.0;
    double heightM = 1.0;
    double angleDeg = 0.0;
    /// A polygon instead of a box (hills, slopes, pits, floating islands): its corners in metres, simple, convex or
    /// not, either winding; solid. When given, x, y, w and h hold its bounding box (centre and size) and angleDeg is
    /// 0; the file gives only the points.
    std::vector<Vec2> points;

    bool isPolygon() const { return !points.empty(); }

    bool operator==(const TerrainDef&) const = default;
};

/// Where birds are launched from, and the level's own band if it has one. Without one a level uses the catalog's
/// slingshot with its world's band force (Catalog::slingshot, levelBand in LevelFlight.hpp): one band per world, so
/// the same pull throws a bird as far on every level of that world. `check` warns when a level sets its own.
struct SlingshotDef
{
    double x = 0.0;
    double y = 1.5;                   ///< height of the pouch, where the bird leaves the slingshot
    std::optional<double> maxForceN;  ///< the band's force at full pull (N)
    std::optional<double> maxPullM;   ///< full pull (m)
    std::optional<double> bandMassKg; ///< the band's moving mass (kg); 0: a massless band (a lesson comparing bands)

    bool ownsBand() const { return maxForceN || maxPullM || bandMassKg; }
    bool operator==(const SlingshotDef&) const = default;
};

/// The air and gravity of a level. Absent terms (zero, or no gusts) are not simulated.
struct EnvironmentDef
{
    double gravity = 9.81;   ///< m/s^2 along -y
    double airDensity = 0.0; ///< kg/m^3; 0 is vacuum (no drag)
    double windX = 0.0;      ///< m/s
    double windY = 0.0;
    std::optional<GustDef> gusts; ///< time-varying wind on top of windX/windY (acts through drag)

    bool operator==(const EnvironmentDef&) const = default;
};

/// A shot that shows off a level (benchmarks time it; designers replay it): angle in degrees, speed in m/s.
struct ReferenceShotDef
{
    double angleDeg = 45.0;
    double speedMps = 0.0;

    bool operator==(const ReferenceShotDef&) const = default;
};

/// This level's values for one catalog material; an absent value keeps the catalog's ("materials" in JSON).
struct MaterialOverrideDef
{
    std::string material;                 ///< catalog name: wood, ice, stone
    std::optional<double> densityKgPerM3; ///< bulk density; the world uses it x the catalog's slab depth
    std::optional<double> friction;       ///< Coulomb friction coefficient
    std::optional<double> restitution;    ///< 0 (no bounce) to 1
    std::optional<double> strengthNs;     ///< impulse a block absorbs before it breaks (N s)

    bool operator==(const MaterialOverrideDef&) const = default;
};

/// A bird the level defines itself, named "custom" in the birds list ("custom_bird" in JSON). Ranges are PhET
/// Projectile Motion Lab's; where they leave what Box2D simulates well, the world collides it as a clamped body
/// (see birdCollisionBody) while its flight uses these true values.
struct CustomBirdDef
{
    double massKg = 4.0;
    double diameterM = 0.5;
    double dragCoefficient = 0.47; ///< Cd; a sphere is about 0.47

    bool operator==(const CustomBirdDef&) const = default;
};

/// The name a level's birds list uses for its custom bird.
inline constexpr const char* kCustomBirdName = "custom";

enum class WorldTheme; // WorldTheme.hpp

/// An outcome a text promises for a shot: over a fan of aims around it, a pig standing in an x range is defeated (by a
/// block that stood in another x range, when given) in at least so many of the aims. Toppling is chaotic: one aim
/// proves little, most of a small fan does.
struct OutcomeClaimDef
{
    double angleDeg = 0.0; ///< the shot the text describes ("shot": [angle, speed])
    double speedMps = 0.0;
    std::array<double, 2> pigX{}; ///< "pig_x": a pig whose x as written is in [min, max] is defeated ...
    std::optional<std::array<double, 2>> byBlockX; ///< "by_block_x": ... by a block whose x as written is in it
    int inAtLeast = 1;                             ///< "in_at_least": of the fan's kOutcomeFanAims aims

    bool operator==(const OutcomeClaimDef&) const = default;
};

/// A material the level's texts say no shot breaks ("cannot_break"): played with every bird the level has, over a
/// grid of first shots and the fan of aims around each, the bird's ability used halfway to its first contact, just
/// before it, at it and not at all (levels/README.md, "Claims").
struct CannotBreakClaimDef
{
    std::string material;
    /// "cause": "bird": only a block the bird's own body breaks counts (its hit; a blast, a falling block or the
    /// ground do not); absent: a block of the material breaking for any reason breaks the claim.
    bool byBirdOnly = false;

    bool operator==(const CannotBreakClaimDef&) const = default;
};

/// Which angles reach a pig at full pull ("full_pull_reach"): the level's first bird at full pull over every angle
/// (kReachAnglesStepDeg apart) first strikes a pig in an x range (its flight reaches it, not a roll or a bounce) only
/// within so many degrees of the best angle, and does at the best angle (levels/README.md, "Claims").
struct ReachClaimDef
{
    /// "pig_x": the bird's first contact is a pig whose x as written is in [min, max] ...
    std::array<double, 2> pigX{};
    double withinDeg = 0.0; ///< "within_deg": ... only for aims this close to best_angle:BIRD

    bool operator==(const ReachClaimDef&) const = default;
};

/// A qualitative promise one of the level's texts makes, as something the program computes for the level (`abalike
/// check` fails when it does not hold): a comparison ("best_angle:red < calm_best_angle:red") or an outcome.
struct ClaimDef
{
    std::string about; ///< the text it backs, as a JSON pointer: "/concept" or "/hints/N"
    std::string holds; ///< EXPRESSION OP EXPRESSION, OP one of < > <= >=, expressions as in the placeholders; empty
                       ///< for an outcome
    std::optional<OutcomeClaimDef> outcome;
    std::optional<CannotBreakClaimDef> cannotBreak;
    std::optional<ReachClaimDef> reach;

    bool operator==(const ClaimDef&) const = default;
};

/// A level, as designers write it in JSON (levels/*.json).
struct LevelDef
{
    int format = 1; ///< version of the file format
    std::string id;
    std::string title;
    std::string episode; ///< id of the campaign episode it belongs to; empty when it stands alone
    std::string lesson;  ///< the physics concept it teaches ("concept" in JSON)
    std::vector<std::string> hints;
    std::vector<ClaimDef> claims; ///< what the texts promise, checked by `abalike check`
    double groundY = 0.0;
    SlingshotDef slingshot;
    std::vector<std::string> birds; ///< bird type names, in launch order
    std::vector<BlockDef> blocks;
    std::vector<PigDef> pigs;
    std::vector<TerrainDef> terrain;
    EnvironmentDef environment;
    std::array<int, 3> starScores{10000, 20000, 30000}; ///< score for one, two and three stars
    std::optional<double> timeLimitS;                   ///< game time (s) to defeat every pig; none when absent
    std::optional<ReferenceShotDef> referenceShot;      ///< a first shot that shows the level off
    /// A sandbox scene (the editor's): it may have no pig, and a campaign refuses it.
    bool sandbox = false;
    std::vector<MaterialOverrideDef> materials; ///< this level's material values, at most one per material
    std::optional<CustomBirdDef> customBird;    ///< the bird the birds list calls "custom"
    /// The scenery's world ("theme"); none: the world of the level's gravity (levelTheme).
    std::optional<WorldTheme> theme;
    std::string sourcePath; ///< file it was loaded from, for messages

    bool operator==(const LevelDef&) const = default;
};

} // namespace abalike
