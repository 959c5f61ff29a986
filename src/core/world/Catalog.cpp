#include "level/JsonLocator.hpp"
#include "level/LevelReader.hpp"
#include "world/CatalogLooks.hpp"

#include <abalike/level/WorldTheme.hpp>

#include <abalike/world/Catalog.hpp>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace abalike
{

namespace embedded
{
extern const char* const kCatalogJson;
}

namespace
{

using nlohmann::json;

double positive(const json& object, const char* key, const std::string& where)
{
    const double value = object.at(key).get<double>();
    if (!(value > 0.0))
        throw std::runtime_error(where + "." + key + " must be > 0");
    return value;
}

SlingshotRules readSlingshot(const json& sling)
{
    SlingshotRules rules;
    rules.maxPullM = positive(sling, "max_pull_m", "slingshot");
    rules.bandMassKg = sling.at("band_mass_kg").get<double>();
    if (!(rules.bandMassKg >= 0.0))
        throw std::runtime_error("slingshot.band_mass_kg must be >= 0");
    const json& forces = sling.at("max_force_n");
    if (!forces.is_object() || forces.empty())
        throw std::runtime_error(
            "slingshot.max_force_n must be an object of band forces by world, {\"earth\": N, ...}");
    for (const auto& [world, force] : forces.items())
    {
        if (!parseWorldTheme(world))
            throw std::runtime_error("slingshot.max_force_n: unknown world \"" + world +
                                     "\" (expected earth, moon, mars, titan or jupiter)");
        rules.worldForceN.emplace_back(world, positive(forces, world.c_str(), "slingshot.max_force_n"));
    }
    if (!forces.contains("earth"))
        throw std::runtime_error("slingshot.max_force_n must give Earth's band force (\"earth\")");
    return rules;
}

template <class T>
const T* findByName(const std::vector<T>& items, std::string_view name)
{
    for (const T& item : items)
        if (item.name == name)
            return &item;
    return nullptr;
}

/// The catalog's rule for birds (the requirements' "characters with unique masses and sizes"): each has a name, a
/// mass and a radius of its own; two birds may share an ability.
void checkBirdsDiffer(const std::vector<BirdType>& birds)
{
    for (std::size_t j = 1; j < birds.size(); ++j)
        for (std::size_t i = 0; i < j; ++i)
        {
            const std::string at = "/birds/" + std::to_string(j);
            const std::string other = "\"" + birds[i].name + "\" (/birds/" + std::to_string(i) + ")";
            if (birds[j].name == birds[i].name)
                throw CatalogError{at + "/name", "a second bird named \"" + birds[j].name + "\": names are unique"};
            if (birds[j].massKg == birds[i].massKg)
                throw CatalogError{at + "/mass_kg", "the same mass as " + other +
                                                        ": every bird has a mass of its own (the game compares birds "
                                                        "by mass)"};
            if (birds[j].radiusM == birds[i].radiusM)
                throw CatalogError{at + "/radius_m", "the same radius as " + other +
                                                         ": every bird has a size of its own (players tell birds "
                                                         "apart by size)"};
        }
}

/// "unknown ability "boomrang" (did you mean "boost"?)", or the list of known names when none is close.
std::string unknownAbility(const std::string& name)
{
    std::vector<std::string> known = AbilityRegistry::names();
    std::string message = "unknown ability \"" + name + "\"";
    if (const auto suggestion = closestMatch(name, known))
        return message + " (did you mean \"" + *suggestion + "\"?)";
    known.insert(known.begin(), std::string(kNoAbility));
    message += " (expected one of:";
    for (std::size_t i = 0; i < known.size(); ++i)
        message += (i == 0 ? " " : ", ") + known[i];
    return message + ")";
}

/// The abilities the birds name, made with the catalog's numbers (its "abilities" block), in the order the birds
/// use them, then any other the block configures.
std::vector<std::shared_ptr<const Ability>> readAbilities(const json& root, std::vector<BirdType>& birds)
{
    const json none = json::object();
    const json* block = root.contains("abilities") ? &root.at("abilities") : nullptr;
    std::vector<std::shared_ptr<const Ability>> made;
    const auto make = [&](const std::string& name, const std::string& pointer) -> std::shared_ptr<const Ability>
    {
        for (const auto& ability : made)
            if (ability->name() == name)
                return ability;
        const AbilityFactory* factory = AbilityRegistry::find(name);
        if (factory == nullptr)
            throw CatalogError{pointer, unknownAbility(name)};
        made.push_back((*factory)(block != nullptr && block->contains(name) ? block->at(name) : none));
        if (made.back()->name() != name)
            throw std::logic_error("the table of abilities makes \"" + std::string(made.back()->name()) + "\" for \"" +
                                   name + "\"");
        return made.back();
    };
    const json& birdList = root.at("birds");
    for (std::size_t i = 0; i < birds.size(); ++i)
    {
        const std::string name = birdList.at(i).at("ability").get<std::string>();
        if (name != kNoAbility)
            birds[i].ability = make(name, "/birds/" + std::to_string(i) + "/ability");
    }
    if (block != nullptr)
        for (const auto& [name, params] : block->items())
            make(name, "/abilities/" + jsonPointerToken(name));
    return made;
}

/// The abilities' "text_values": each names one of its ability's numbers.
std::vector<AbilityTextValue> readAbilityTextValues(const json& root,
                                                    const std::vector<std::shared_ptr<const Ability>>& made)
{
    std::vector<AbilityTextValue> values;
    if (!root.contains("abilities"))
        return values;
    for (const auto& [ability, params] : root.at("abilities").items())
    {
        if (!params.contains("text_values"))
            continue;
        const std::string at = "/abilities/" + jsonPointerToken(ability) + "/text_values";
        const json& declared = params.at("text_values");
        if (!declared.is_object())
            throw CatalogError{at, "expected an object of placeholder names"};
        // (a named copy: clang 14 cannot capture a structured binding)
        const std::string& abilityName = ability;
        const auto owner =
            std::find_if(made.begin(), made.end(), [&](const auto& a) { return a->name() == abilityName; });
        if (owner == made.end())
            continue; // readAbilities has refused an ability it does not know
        for (const auto& [name, value] : declared.items())
        {
            const std::string here = at + "/" + jsonPointerToken(name);
            if (!value.is_object() || !value.contains("number") || !value.at("number").is_string())
                throw CatalogError{here, "expected {\"number\": KEY, \"meaning\": TEXT, \"unit\": TEXT}"};
            AbilityTextValue text{name, ability, value.at("number").get<std::string>(), value.value("meaning", ""),
                                  value.value("unit", "")};
            try
            {
                (void)(*owner)->number(text.number);
            }
            catch (const std::out_of_range&)
            {
                throw CatalogError{here + "/number", ability + " has no number \"" + text.number + "\""};
            }
            for (const AbilityTextValue& other : values)
                if (other.name == name)
                    throw CatalogError{here, "the placeholder \"" + name + "\" is declared twice"};
            values.push_back(std::move(text));
        }
    }
    return values;
}

} // namespace

Catalog Catalog::fromJson(std::string_view text, const std::string& fileName)
{
    Catalog catalog;
    try
    {
        const json root = json::parse(text);
        catalog.m_slabDepthM = root.contains("slab_depth_m") ? positive(root, "slab_depth_m", "catalog") : 0.1;
        catalog.m_maxLaunchSpeedMps = positive(root.at("slingshot"), "max_launch_speed_mps", "slingshot");
        catalog.m_slingshot = readSlingshot(root.at("slingshot"));
        const json& scoring = root.at("scoring");
        catalog.m_scoring.pointsPerUnusedBird = scoring.at("points_per_unused_bird").get<int>();
        catalog.m_scoring.efficiencyPointsPerExtraPig = scoring.value("efficiency_points_per_extra_pig", 5000);
        catalog.m_scoring.accuracyPointsPerShot = scoring.value("accuracy_points_per_shot", 1000);
        catalog.m_scoring.accuracyToleranceM = scoring.value("accuracy_tolerance_m", 0.05);
        if (!(catalog.m_scoring.accuracyToleranceM > 0.0))
            throw std::runtime_error("scoring.accuracy_tolerance_m must be > 0");
        catalog.m_damageSpeedThreshold = positive(root.at("damage"), "speed_threshold_mps", "damage");
        if (root.contains("ground"))
            catalog.m_groundFriction = root.at("ground").value("friction", 0.8);
        if (root.contains("rolling"))
        {
            catalog.m_rollingResistance = root.at("rolling").at("resistance").get<double>();
            if (!(catalog.m_rollingResistance >= 0.0 && catalog.m_rollingResistance < 1.0))
                throw std::runtime_error("rolling.resistance must be in [0, 1)");
        }
        for (std::size_t i = 0; i < root.at("materials").size(); ++i)
        {
            const json& m = root.at("materials").at(i);
            const std::string where = "material " + m.at("name").get<std::string>();
            Material material{m.at("name").get<std::string>(),   positive(m, "density_kg_per_m2", where),
                              m.at("friction").get<double>(),    m.at("restitution").get<double>(),
                              positive(m, "strength_ns", where), m.at("points").get<int>(),
                              m.value("note", std::string())};
            // The areal density Box2D uses must be the documented bulk density times the slab depth.
            material.bulkDensityKgPerM3 =
                m.value("bulk_density_kg_per_m3", material.densityKgPerM2 / catalog.m_slabDepthM);
            if (std::abs(material.bulkDensityKgPerM3 * catalog.m_slabDepthM - material.densityKgPerM2) >
                1e-9 * material.densityKgPerM2)
                throw std::runtime_error(where + ": density_kg_per_m2 must be bulk_density_kg_per_m3 x slab_depth_m");
            material.look = readMaterialLook(m, "/materials/" + std::to_string(i));
            if (m.contains("blast"))
            {
                material.blastRadiusM = positive(m.at("blast"), "radius_m", where + " blast");
                material.blastImpulseNs = positive(m.at("blast"), "impulse_ns", where + " blast");
            }
            catalog.m_materials.push_back(std::move(material));
        }
        for (std::size_t i = 0; i < root.at("birds").size(); ++i)
        {
            const json& b = root.at("birds").at(i);
            const std::string where = "bird " + b.at("name").get<std::string>();
            BirdType bird{b.at("name").get<std::string>(), positive(b, "mass_kg", where),
                          positive(b, "radius_m", where), positive(b, "drag_coefficient", where)};
            bird.friction = b.value("friction", bird.friction);
            bird.restitution = b.value("restitution", bird.restitution);
            bird.look = readBirdLook(b, "/birds/" + std::to_string(i));
            catalog.m_birds.push_back(std::move(bird));
        }
        checkBirdsDiffer(catalog.m_birds);
        for (const json& p : root.at("pigs"))
        {
            const std::string where = "pig " + p.at("name").get<std::string>();
            PigType pig{p.at("name").get<std::string>(),
                        positive(p, "radius_m", where),
                        positive(p, "density_kg_per_m2", where),
                        positive(p, "health_ns", where),
                        p.at("points").get<int>(),
                        p.at("helmet").get<bool>()};
            pig.friction = p.value("friction", pig.friction);
            pig.restitution = p.value("restitution", pig.restitution);
            catalog.m_pigs.push_back(std::move(pig));
        }
        if (root.contains("model_player"))
        {
            const json& player = root.at("model_player");
            catalog.m_playerAim.angleSigmaDeg = player.value("angle_sigma_deg", 0.5);
            catalog.m_playerAim.pullSigma = player.value("pull_sigma", 0.01);
            if (!(catalog.m_playerAim.angleSigmaDeg >= 0.0) || !(catalog.m_playerAim.pullSigma >= 0.0))
                throw std::runtime_error("model_player: the aim's standard deviations must be >= 0");
        }
        catalog.m_abilities = readAbilities(root, catalog.m_birds);
        catalog.m_abilityTextValues = readAbilityTextValues(root, catalog.m_abilities);
    }
    catch (const CatalogError& e)
    {
        const auto [line, column] = JsonLocator(text).locate(e.pointer);
        throw std::runtime_error(fileName + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                                 e.pointer + ": " + e.message);
    }
    catch (const json::exception& e)
    {
        throw std::runtime_error(fileName + ": " + e.what());
    }
    return catalog;
}

std::string_view Catalog::builtinJson()
{
    return embedded::kCatalogJson;
}

const Catalog& Catalog::builtin()
{
    static const Catalog catalog = fromJson(embedded::kCatalogJson);
    return catalog;
}

const Ability* Catalog::findAbility(std::string_view name) const
{
    for (const auto& ability : m_abilities)
        if (ability->name() == name)
            return ability.get();
    return nullptr;
}

const Material* Catalog::findMaterial(std::string_view name) const
{
    return findByName(m_materials, name);
}

const BirdType* Catalog::findBird(std::string_view name) const
{
    return findByName(m_birds, name);
}

void Catalog::replaceMaterial(const Material& material)
{
    for (Material& existing : m_materials)
        if (existing.name == material.name)
        {
            existing = material;
            return;
        }
    throw std::invalid_argument("unknown material \"" + material.name + "\"");
}

void Catalog::putBird(const BirdType& bird)
{
    for (BirdType& existing : m_birds)
        if (existing.name == bird.name)
        {
            existing = bird;
            return;
        }
    m_birds.push_back(bird);
}

const PigType* Catalog::findPig(std::string_view name) const
{
    return findByName(m_pigs, name);
}

double SlingshotRules::forceFor(std::string_view world) const
{
    double earth = 0.0;
    for (const auto& [name, force] : worldForceN)
    {
        if (name == world)
            return force;
        if (name == "earth")
            earth = force;
    }
    return earth;
}

} // namespace abalike
