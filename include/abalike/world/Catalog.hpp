#pragma once

#include <string>
#include <string_view>
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
    double strengthNs = 0.0; ///< normal impulse a block can absorb before it breaks (N s)
    int points = 0;          ///< score when destroyed
    std::string note;        ///< where the numbers come from
};

/// A kind of bird: the spec's "unique masses and sizes".
struct BirdType
{
    std::string name;
    double massKg = 0.0;
    double radiusM = 0.0;
    double dragCoefficient = 0.47; ///< Cd of a sphere
    std::string ability;           ///< "none", "split", "boost", "explode", "egg"
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
};

/// Balance data (materials, birds, pigs), kept in one data file (assets/catalog.json) that is compiled into
/// the core, so the game, the levels, the tests and the docs all read the same table.
class Catalog
{
public:
    /// The table compiled in from assets/catalog.json.
    static const Catalog& builtin();

    /// Parses a catalog from JSON text; throws std::runtime_error naming what is wrong.
    static Catalog fromJson(std::string_view text);

    const Material* findMaterial(std::string_view name) const;
    const BirdType* findBird(std::string_view name) const;
    const PigType* findPig(std::string_view name) const;

    const std::vector<Material>& materials() const { return m_materials; }
    const std::vector<BirdType>& birds() const { return m_birds; }
    const std::vector<PigType>& pigs() const { return m_pigs; }

    double slingshotReleaseTimeS() const { return m_releaseTimeS; }
    int pointsPerUnusedBird() const { return m_pointsPerUnusedBird; }
    double damageSpeedThresholdMps() const { return m_damageSpeedThreshold; }

private:
    std::vector<Material> m_materials;
    std::vector<BirdType> m_birds;
    std::vector<PigType> m_pigs;
    double m_releaseTimeS = 0.1;
    int m_pointsPerUnusedBird = 10000;
    double m_damageSpeedThreshold = 0.5;
};

} // namespace abalike
