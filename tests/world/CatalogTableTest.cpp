#include "CatalogLoadError.hpp"

#include <abalike/world/CatalogTable.hpp>
#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>

namespace abalike
{
namespace
{

const std::string kDocs = std::string(ABALIKE_SOURCE_DIR) + "/docs/materials.md";

TEST(CatalogTable, DocsMaterialsIsGeneratedFromTheCatalog)
{
    const std::string generated = catalogMarkdown(Catalog::builtin());
    if (std::getenv("ABALIKE_UPDATE_DOCS") != nullptr)
    {
        std::ofstream(kDocs, std::ios::binary) << generated;
        GTEST_SKIP() << "wrote " << kDocs;
    }
    std::ifstream in(kDocs, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), generated) << kDocs << " is out of date: run with ABALIKE_UPDATE_DOCS=1 to regenerate";
}

TEST(CatalogTable, SameSizeMaterialsStayInsideTenToOne)
{
    const auto& materials = Catalog::builtin().materials();
    for (const Material& upper : materials)
        for (const Material& lower : materials)
            EXPECT_LE(upper.densityKgPerM2 / lower.densityKgPerM2, 10.0) << upper.name << " on " << lower.name;
}

TEST(CatalogTable, ArealDensityIsBulkDensityTimesSlabDepth)
{
    for (const Material& m : Catalog::builtin().materials())
        EXPECT_DOUBLE_EQ(m.densityKgPerM2, m.bulkDensityKgPerM3 * Catalog::builtin().slabDepthM()) << m.name;
    EXPECT_THROW(Catalog::fromJson(R"({"slab_depth_m": 0.1, "slingshot": {"max_launch_speed_mps": 864},
        "scoring": {"points_per_unused_bird": 1}, "damage": {"speed_threshold_mps": 0.5},
        "materials": [{"name": "x", "bulk_density_kg_per_m3": 500, "density_kg_per_m2": 40, "friction": 0.5,
                       "restitution": 0.1, "strength_ns": 10, "points": 1}],
        "birds": [], "pigs": []})"),
                 std::runtime_error);
}

TEST(CatalogTable, IceIsLightSlipperyAndBrittleStoneHeavyAndTough)
{
    const Catalog& c = Catalog::builtin();
    const Material& ice = *c.findMaterial("ice");
    const Material& wood = *c.findMaterial("wood");
    const Material& stone = *c.findMaterial("stone");
    EXPECT_LT(ice.densityKgPerM2, wood.densityKgPerM2);
    EXPECT_LT(ice.friction, wood.friction);
    EXPECT_LT(ice.strengthNs, wood.strengthNs);
    EXPECT_GT(stone.densityKgPerM2, wood.densityKgPerM2);
    EXPECT_GT(stone.strengthNs, wood.strengthNs);
}

TEST(CatalogTable, TheSlingshotGivesABandForEachKnownWorldAndEarthsAtLeast)
{
    nlohmann::json catalog = nlohmann::json::parse(Catalog::builtinJson());
    catalog["slingshot"]["max_force_n"]["marz"] = 1400;
    std::string error = test::catalogLoadError(catalog.dump(2));
    EXPECT_NE(error.find("unknown world \"marz\" (expected earth, moon, mars, titan or jupiter)"), std::string::npos)
        << error;
    catalog["slingshot"]["max_force_n"].erase("marz");
    catalog["slingshot"]["max_force_n"].erase("earth");
    error = test::catalogLoadError(catalog.dump(2));
    EXPECT_NE(error.find("Earth's band force"), std::string::npos) << error;
    const SlingshotRules& rules = Catalog::builtin().slingshot();
    EXPECT_DOUBLE_EQ(rules.forceFor("earth"), 8100.0);
    EXPECT_DOUBLE_EQ(rules.forceFor("mars"), 1406.25);
    EXPECT_DOUBLE_EQ(rules.forceFor("pluto"), 8100.0) << "a world the catalog does not list takes Earth's";
    EXPECT_DOUBLE_EQ(rules.bandMassKg, 14.0);
}

TEST(CatalogTable, ABirdWithAnotherBirdsMassOrSizeIsALocatedError)
{
    // The rule is checked where the catalog loads: a bird copied from the first one and given only a new name must be
    // told which number to change, at its line.
    nlohmann::json catalog = nlohmann::json::parse(Catalog::builtinJson());
    nlohmann::json copy = catalog.at("birds").at(0);
    const std::string first = copy.at("name").get<std::string>();
    copy["name"] = first + "-copy";
    catalog["birds"].push_back(copy);
    const std::string last = std::to_string(catalog.at("birds").size() - 1);
    const std::string text = catalog.dump(2);
    std::string error = test::catalogLoadError(text);
    EXPECT_NE(error.find("/birds/" + last + "/mass_kg: the same mass as \"" + first + "\" (/birds/0)"),
              std::string::npos)
        << error;
    EXPECT_EQ(error.rfind("assets/catalog.json:", 0), 0u) << error;

    catalog["birds"].back()["mass_kg"] = copy.at("mass_kg").get<double>() * 1.5 + 0.125;
    error = test::catalogLoadError(catalog.dump(2));
    EXPECT_NE(error.find("/birds/" + last + "/radius_m: the same radius as \"" + first + "\""), std::string::npos)
        << error;

    catalog["birds"].back()["radius_m"] = copy.at("radius_m").get<double>() * 1.5 + 0.125;
    catalog["birds"].back()["name"] = first;
    error = test::catalogLoadError(catalog.dump(2));
    EXPECT_NE(error.find("/birds/" + last + "/name: a second bird named \"" + first + "\""), std::string::npos)
        << error;

    catalog["birds"].back()["name"] = first + "-copy";
    EXPECT_EQ(test::catalogLoadError(catalog.dump(2)), "") << "two birds may share an ability";
}

} // namespace
} // namespace abalike
