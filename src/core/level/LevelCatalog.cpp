#include <abalike/level/LevelCatalog.hpp>

namespace abalike
{

BirdType customBirdType(const CustomBirdDef& def)
{
    BirdType bird;
    bird.name = kCustomBirdName;
    bird.massKg = def.massKg;
    bird.radiusM = def.diameterM / 2.0;
    bird.dragCoefficient = def.dragCoefficient;
    return bird;
}

Catalog levelCatalog(const LevelDef& level, const Catalog& base)
{
    Catalog catalog = base;
    for (const MaterialOverrideDef& item : level.materials)
    {
        const Material* original = base.findMaterial(item.material);
        if (original == nullptr)
            continue; // the loader has reported it; a world built anyway fails on the block that uses it
        Material material = *original;
        if (item.densityKgPerM3)
        {
            material.bulkDensityKgPerM3 = *item.densityKgPerM3;
            material.densityKgPerM2 = *item.densityKgPerM3 * base.slabDepthM();
        }
        material.friction = item.friction.value_or(material.friction);
        material.restitution = item.restitution.value_or(material.restitution);
        material.strengthNs = item.strengthNs.value_or(material.strengthNs);
        catalog.replaceMaterial(material);
    }
    if (level.customBird)
        catalog.putBird(customBirdType(*level.customBird));
    return catalog;
}

} // namespace abalike
