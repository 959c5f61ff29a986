#include "level/LevelSections.hpp"
#include <abalike/level/LevelLimits.hpp>

#include <abalike/world/Catalog.hpp>

#include <algorithm>

namespace abalike
{

namespace
{

using json = nlohmann::json;
using namespace abalike::limits;

/// An optional number: none when the key is absent or wrong (the reader has reported it).
std::optional<double> optionalNumber(LevelReader& r, const json& object, const std::string& pointer, const char* key,
                                     const NumberRange& range)
{
    const auto it = object.find(key);
    if (it == object.end())
        return std::nullopt;
    return r.numberAt(*it, pointer + "/" + key, range);
}

} // namespace

void readMaterialOverrides(LevelReader& r, const json& root, LevelDef& level, const Catalog& catalog)
{
    const auto it = root.find("materials");
    if (it == root.end())
        return;
    std::vector<std::string> names;
    for (const Material& material : catalog.materials())
        names.push_back(material.name);
    if (!it->is_object())
    {
        r.error("/materials", "expected an object of material names, e.g. {\"wood\": {\"friction\": 0.3}}, got " +
                                  describeJsonType(*it));
        return;
    }
    // Every key must be a material; an unknown one gets a suggestion like any unknown key.
    for (const auto& [key, value] : it->items())
        if (std::find(names.begin(), names.end(), key) == names.end())
        {
            std::string message = "unknown material \"" + key + "\"";
            if (const auto suggestion = closestMatch(key, names))
                message += " (did you mean \"" + *suggestion + "\"?)";
            r.keyError("/materials/" + key, message);
        }
    for (const std::string& name : names)
    {
        const auto entry = it->find(name);
        if (entry == it->end())
            continue;
        const std::string p = "/materials/" + name;
        if (!r.object(*entry, p, {"density_kg_per_m3", "friction", "restitution", "strength_ns"}))
            continue;
        MaterialOverrideDef item;
        item.material = name;
        item.densityKgPerM3 = optionalNumber(r, *entry, p, "density_kg_per_m3",
                                             NumberRange{kMinMaterialDensity, kMaxMaterialDensity, "kg/m^3"});
        item.friction = optionalNumber(r, *entry, p, "friction", NumberRange{0.0, kMaxFriction});
        item.restitution = optionalNumber(r, *entry, p, "restitution", NumberRange{0.0, 1.0});
        item.strengthNs =
            optionalNumber(r, *entry, p, "strength_ns", NumberRange{kMinStrengthNs, kMaxStrengthNs, "N s"});
        level.materials.push_back(item);
    }
}

void readCustomBird(LevelReader& r, const json& root, LevelDef& level)
{
    const auto it = root.find("custom_bird");
    if (it == root.end() || !r.object(*it, "/custom_bird", {"mass_kg", "diameter_m", "drag_coefficient"}))
        return;
    const std::string p = "/custom_bird";
    CustomBirdDef bird;
    bird.massKg = r.number(*it, p, "mass_kg", bird.massKg, true, NumberRange{kMinBirdMassKg, kMaxBirdMassKg, "kg"});
    bird.diameterM =
        r.number(*it, p, "diameter_m", bird.diameterM, true, NumberRange{kMinBirdDiameterM, kMaxBirdDiameterM, "m"});
    bird.dragCoefficient = r.number(*it, p, "drag_coefficient", bird.dragCoefficient, true,
                                    NumberRange{kMinDragCoefficient, kMaxDragCoefficient});
    level.customBird = bird;
}

} // namespace abalike
