#pragma once

#include <abalike/world/Ability.hpp>
#include <abalike/world/Looks.hpp>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace abalike
{

/// A building material. Areal density: Box2D is 2D, so a block's mass is density x area.
struct Material
{
    std::string name;
    double densityKgPerM2 = 0.0;
    double friction = 0.0;
    double restitution = 0.0;
    double strengthNs = 0.0;         ///< normal impulse a block can absorb before it breaks (N s)
    int points = 0;                  ///< score when destroyed
    std::string note;                ///< where the numbers come from
    double bulkDensityKgPerM3 = 0.0; ///< the real material's density; areal density = this x slab depth
    /// A material that explodes when it breaks (TNT): every block and pig whose centre is within blastRadiusM gets
    /// blastImpulseNs (1 - d / R) radially, as push and as damage. 0: it does not explode.
    double blastRadiusM = 0.0;
    double blastImpulseNs = 0.0;
    MaterialLook look{}; ///< how the game draws it, breaks it into debris and sounds it
};

/// A kind of bird: the spec's "unique masses and sizes".
struct BirdType
{
    std::string name;
    double massKg = 0.0;
    double radiusM = 0.0;
    double dragCoefficient = 0.47;            ///< Cd of a sphere
    std::shared_ptr<const Ability> ability{}; ///< null: the bird has none
    double friction = 0.6;
    double restitution = 0.3;
    BirdLook look{};

    /// The ability's name in the catalog, "none" for a bird without one.
    std::string_view abilityName() const { return ability ? ability->name() : kNoAbility; }
};

/// A kind of pig.
struct PigType
{
    std::string name;
    double radiusM = 0.0;
    double densityKgPerM2 = 0.0;
    double healthNs = 0.0; ///< impulse it absorbs before it is defeated (N s)
    int points = 0;
    bool helmet = false;
    double friction = 0.6;
    double restitution = 0.2;
};

/// Score rules beyond the per-block and per-pig points.
struct ScoringRules
{
    int pointsPerUnusedBird = 10000;        ///< efficiency: each bird left when the level is won
    int efficiencyPointsPerExtraPig = 5000; ///< efficiency: each pig beyond the first defeated in one shot
    int accuracyPointsPerShot = 1000;       ///< accuracy: a first contact exactly where predicted
    double accuracyToleranceM = 0.05;       ///< accuracy: deviation at which the accuracy points reach zero
};

/// The model player that measures a level's difficulty (design/ModelPlayer.hpp): how unsteady its aim is.
struct PlayerAim
{
    double angleSigmaDeg = 0.5; ///< standard deviation of the launch angle
    double pullSigma = 0.01;    ///< standard deviation of the pull, as a share of the full pull
};

/// The game's one slingshot (assets/catalog.json "slingshot"): a linear band of full pull maxPullM whose pouch and
/// rubber move with the bird as a lumped mass bandMassKg, and one band force per world, so that the same pull throws
/// the same bird as far on every level of a world (docs/slingshot.md).
struct SlingshotRules
{
    double maxPullM = 2.0;
    double bandMassKg = 14.0;
    /// A world's band force at full pull (N), by world name (WorldTheme: "earth", "moon", ...); Earth's is required.
    std::vector<std::pair<std::string, double>> worldForceN;

    /// The band force of the named world; Earth's for a name the catalog does not list.
    double forceFor(std::string_view world) const;
};

/// A number of an ability that level texts may name as a placeholder ("{egg_mass}"): declared in the ability's block
/// of the catalog ("text_values"), so that no code names an ability.
struct AbilityTextValue
{
    std::string name;    ///< the placeholder's name
    std::string ability; ///< the ability whose number it is
    std::string number;  ///< the number's key in the ability's block ("mass_kg")
    std::string meaning; ///< what it is, for the level guide and error messages
    std::string unit;
};

/// Balance data (materials, birds, pigs), kept in one data file (assets/catalog.json) that is compiled into
/// the core, so the game, the levels, the tests and the docs all read the same table.
class Catalog
{
public:
    /// The table compiled in from assets/catalog.json.
    static const Catalog& builtin();
    /// Its text, for a variant of it (a benchmark's rules before a change).
    static std::string_view builtinJson();

    /// Parses a catalog from JSON text; throws std::runtime_error naming what is wrong, with the file's name and,
    /// for a name that matches nothing (an ability), its line and column.
    static Catalog fromJson(std::string_view text, const std::string& fileName = "assets/catalog.json");

    const Material* findMaterial(std::string_view name) const;
    const BirdType* findBird(std::string_view name) const;
    const PigType* findPig(std::string_view name) const;

    /// Replaces the material of the same name (a level's own values); throws std::invalid_argument if unknown.
    void replaceMaterial(const Material& material);
    /// Adds a bird type, or replaces the one of the same name (a level's custom bird).
    void putBird(const BirdType& bird);

    const std::vector<Material>& materials() const { return m_materials; }
    const std::vector<BirdType>& birds() const { return m_birds; }
    const std::vector<PigType>& pigs() const { return m_pigs; }

    int pointsPerUnusedBird() const { return m_scoring.pointsPerUnusedBird; }
    const ScoringRules& scoring() const { return m_scoring; }
    const PlayerAim& playerAim() const { return m_playerAim; }
    double damageSpeedThresholdMps() const { return m_damageSpeedThreshold; }
    /// The abilities the birds use, in the order the birds list them, then any other the catalog configures.
    const std::vector<std::shared_ptr<const Ability>>& abilities() const { return m_abilities; }
    /// An ability with the catalog's numbers, or null when no bird uses it and the catalog does not configure it.
    const Ability* findAbility(std::string_view name) const;
    /// The numbers the abilities let level texts name, in the order of the catalog's abilities block.
    const std::vector<AbilityTextValue>& abilityTextValues() const { return m_abilityTextValues; }
    double groundFriction() const { return m_groundFriction; }
    /// Rolling resistance coefficient of pigs and round blocks: the torque against rolling is at most this x the
    /// normal force x the radius.
    double rollingResistance() const { return m_rollingResistance; }
    /// Fastest launch the game allows (m/s), whatever the slingshot: the measured speed up to which the world
    /// neither tunnels nor leaves the preview (docs/world-physics.md, "Tunneling").
    double maxLaunchSpeedMps() const { return m_maxLaunchSpeedMps; }
    /// The slingshot every level uses unless it sets its own band.
    const SlingshotRules& slingshot() const { return m_slingshot; }
    /// Depth of the slab a 2D block stands for (m): areal density = bulk density x depth.
    double slabDepthM() const { return m_slabDepthM; }

private:
    std::vector<Material> m_materials;
    std::vector<BirdType> m_birds;
    std::vector<PigType> m_pigs;
    std::vector<std::shared_ptr<const Ability>> m_abilities;
    std::vector<AbilityTextValue> m_abilityTextValues;
    ScoringRules m_scoring;
    PlayerAim m_playerAim;
    double m_damageSpeedThreshold = 0.5;
    double m_groundFriction = 0.8;
    double m_rollingResistance = 0.0;
    double m_maxLaunchSpeedMps = 100.0;
    SlingshotRules m_slingshot;
    double m_slabDepthM = 0.1;
};

} // namespace abalike
