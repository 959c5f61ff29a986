// The looks the catalog gives materials and birds: read as written, and every mistake a located error. The tests work
// on the parsed catalog (whatever its birds, materials and layout), never on its text.
#include "CatalogLoadError.hpp"

#include <abalike/world/Catalog.hpp>
#include <cstdio>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <string>

namespace abalike
{
namespace
{

nlohmann::json builtinCatalog()
{
    return nlohmann::json::parse(Catalog::builtinJson());
}

/// A colour as the catalog writes it: "#rrggbb", or "#rrggbbaa" when not opaque.
std::string hex(const Rgba& rgba)
{
    char text[16];
    if (rgba[3] == 255)
        std::snprintf(text, sizeof text, "#%02x%02x%02x", rgba[0], rgba[1], rgba[2]);
    else
        std::snprintf(text, sizeof text, "#%02x%02x%02x%02x", rgba[0], rgba[1], rgba[2], rgba[3]);
    return text;
}

TEST(CatalogLooks, MaterialsAndBirdsHaveTheLooksTheCatalogGives)
{
    const Catalog& catalog = Catalog::builtin();
    const nlohmann::json json = builtinCatalog();
    ASSERT_EQ(catalog.materials().size(), json.at("materials").size());
    for (std::size_t i = 0; i < catalog.materials().size(); ++i)
    {
        const Material& m = catalog.materials()[i];
        const nlohmann::json& look = json.at("materials").at(i).at("look");
        EXPECT_EQ(surfaceKindName(m.look.surface), look.at("surface").get<std::string>()) << m.name;
        EXPECT_EQ(hex(m.look.fill), look.at("fill").get<std::string>()) << m.name;
        EXPECT_EQ(m.look.label, look.at("label").get<std::string>()) << m.name;
    }
    ASSERT_EQ(catalog.birds().size(), json.at("birds").size());
    for (std::size_t i = 0; i < catalog.birds().size(); ++i)
    {
        const BirdType& b = catalog.birds()[i];
        const nlohmann::json& look = json.at("birds").at(i).at("look");
        EXPECT_EQ(hex(b.look.body), look.at("body").get<std::string>()) << b.name;
        EXPECT_EQ(hex(b.look.brow), look.at("brow").get<std::string>()) << b.name;
    }
    // Every bird looks different from every other.
    const auto& birds = catalog.birds();
    for (std::size_t i = 0; i < birds.size(); ++i)
        for (std::size_t j = i + 1; j < birds.size(); ++j)
            EXPECT_NE(birds[i].look.body, birds[j].look.body) << birds[i].name << " " << birds[j].name;
}

TEST(CatalogLooks, AnUnknownSurfaceIsALocatedErrorWithASuggestion)
{
    nlohmann::json json = builtinCatalog();
    const std::size_t last = json.at("materials").size() - 1;
    const std::string surface = json.at("materials").at(last).at("look").at("surface");
    const std::string misspelt = surface.substr(0, 1) + surface; // "ccrate": one letter off
    json["materials"][last]["look"]["surface"] = misspelt;
    const std::string error = test::catalogLoadError(json.dump(2));
    EXPECT_EQ(error.rfind("assets/catalog.json:", 0), 0u) << error;
    EXPECT_NE(error.find("/materials/" + std::to_string(last) + "/look/surface: unknown surface \"" + misspelt +
                         "\" (did you mean \"" + surface + "\"?)"),
              std::string::npos)
        << error;
}

TEST(CatalogLooks, ABadColourIsALocatedError)
{
    nlohmann::json json = builtinCatalog();
    json["birds"][1]["look"]["body"] = "blue";
    const std::string error = test::catalogLoadError(json.dump(2));
    EXPECT_NE(error.find("/birds/1/look/body: expected a colour \"#rrggbb\" or \"#rrggbbaa\", got \"blue\""),
              std::string::npos)
        << error;
    json["birds"][1]["look"]["body"] = "#4e96e";
    const std::string shortHex = test::catalogLoadError(json.dump(2));
    EXPECT_NE(shortHex.find("/birds/1/look/body"), std::string::npos) << shortHex;
}

TEST(CatalogLooks, ABirdWithoutALookIsAnErrorNotARedBird)
{
    nlohmann::json json = builtinCatalog();
    json["birds"][2].erase("look");
    const std::string error = test::catalogLoadError(json.dump(2));
    EXPECT_NE(error.find("/birds/2: needs a \"look\" object"), std::string::npos) << error;
}

} // namespace
} // namespace abalike
