#include <abalike/world/Catalog.hpp>

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

template <class T>
const T* findByName(const std::vector<T>& items, std::string_view name)
{
    for (const T& item : items)
        if (item.name == name)
            return &item;
    return nullptr;
}

} // namespace

Catalog Catalog::fromJson(std::string_view text)
{
    Catalog catalog;
    try
    {
        const json root = json::parse(text);
        catalog.m_releaseTimeS = positive(root.at("slingshot"), "release_time_s", "slingshot");
        catalog.m_pointsPerUnusedBird = root.at("scoring").at("points_per_unused_bird").get<int>();
        catalog.m_damageSpeedThreshold = positive(root.at("damage"), "speed_threshold_mps", "damage");
        for (const json& m : root.at("materials"))
        {
            const std::string where = "material " + m.at("name").get<std::string>();
            catalog.m_materials.push_back({m.at("name").get<std::string>(), positive(m, "density_kg_per_m2", where),
                                           m.at("friction").get<double>(), m.at("restitution").get<double>(),
                                           positive(m, "strength_ns", where), m.at("points").get<int>(),
                                           m.value("note", std::string())});
        }
        for (const json& b : root.at("birds"))
        {
            const std::string where = "bird " + b.at("name").get<std::string>();
            catalog.m_birds.push_back({b.at("name").get<std::string>(), positive(b, "mass_kg", where),
                                       positive(b, "radius_m", where), positive(b, "drag_coefficient", where),
                                       b.at("ability").get<std::string>()});
        }
        for (const json& p : root.at("pigs"))
        {
            const std::string where = "pig " + p.at("name").get<std::string>();
            catalog.m_pigs.push_back({p.at("name").get<std::string>(), positive(p, "radius_m", where),
                                      positive(p, "density_kg_per_m2", where), positive(p, "health_ns", where),
                                      p.at("points").get<int>(), p.at("helmet").get<bool>()});
        }
    }
    catch (const json::exception& e)
    {
        throw std::runtime_error(std::string("catalog: ") + e.what());
    }
    return catalog;
}

const Catalog& Catalog::builtin()
{
    static const Catalog catalog = fromJson(embedded::kCatalogJson);
    return catalog;
}

const Material* Catalog::findMaterial(std::string_view name) const
{
    return findByName(m_materials, name);
}

const BirdType* Catalog::findBird(std::string_view name) const
{
    return findByName(m_birds, name);
}

const PigType* Catalog::findPig(std::string_view name) const
{
    return findByName(m_pigs, name);
}

} // namespace abalike
