#include "CatalogLoadError.hpp"

#include <abalike/world/Catalog.hpp>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

namespace abalike
{
namespace
{

std::string catalogWith(const std::string& from, const std::string& to)
{
    std::ifstream in(std::string(ABALIKE_SOURCE_DIR) + "/assets/catalog.json");
    std::stringstream buffer;
    buffer << in.rdbuf();
    std::string text = buffer.str();
    const std::size_t at = text.find(from);
    if (at == std::string::npos)
        throw std::runtime_error("not in the catalog: " + from);
    return text.replace(at, from.size(), to);
}

TEST(CatalogLooks, MaterialsAndBirdsHaveTheLooksTheCatalogGives)
{
    const Catalog& catalog = Catalog::builtin();
    EXPECT_EQ(catalog.findMaterial("wood")->look.surface, SurfaceKind::Grain);
    EXPECT_EQ(catalog.findMaterial("ice")->look.surface, SurfaceKind::Frost);
    EXPECT_EQ(catalog.findMaterial("stone")->look.surface, SurfaceKind::Masonry);
    EXPECT_EQ(catalog.findMaterial("tnt")->look.surface, SurfaceKind::Crate);
    EXPECT_EQ(catalog.findMaterial("tnt")->look.label, "TNT");
    EXPECT_EQ(catalog.findMaterial("ice")->look.fill, (Rgba{178, 224, 250, 185}));
    EXPECT_EQ(catalog.findBird("blue")->look.body, (Rgba{78, 150, 232, 255}));
    // Every bird looks different from every other.
    const auto& birds = catalog.birds();
    for (std::size_t i = 0; i < birds.size(); ++i)
        for (std::size_t j = i + 1; j < birds.size(); ++j)
            EXPECT_NE(birds[i].look.body, birds[j].look.body) << birds[i].name << " " << birds[j].name;
}

TEST(CatalogLooks, AnUnknownSurfaceIsALocatedErrorWithASuggestion)
{
    const std::string error =
        test::catalogLoadError(catalogWith(R"("surface": "masonry")", R"("surface": "masonary")"));
    EXPECT_NE(error.find("assets/catalog.json:"), std::string::npos) << error;
    EXPECT_NE(error.find("/materials/2/look/surface: unknown surface \"masonary\" (did you mean \"masonry\"?)"),
              std::string::npos)
        << error;
}

TEST(CatalogLooks, ABadColourIsALocatedError)
{
    const std::string error = test::catalogLoadError(catalogWith(R"("body": "#4e96e8")", R"("body": "blue")"));
    EXPECT_NE(error.find("/birds/1/look/body: expected a colour \"#rrggbb\" or \"#rrggbbaa\", got \"blue\""),
              std::string::npos)
        << error;
    const std::string shortHex = test::catalogLoadError(catalogWith(R"("body": "#4e96e8")", R"("body": "#4e96e")"));
    EXPECT_NE(shortHex.find("/birds/1/look/body"), std::string::npos) << shortHex;
}

TEST(CatalogLooks, ABirdWithoutALookIsAnErrorNotARedBird)
{
    const std::string error = test::catalogLoadError(catalogWith(
        R"(,
      "look": { "body": "#fad428", "outline": "#aa820a", "belly": "#fff0aa", "brow": "#3c280a" })",
        ""));
    EXPECT_NE(error.find("/birds/2: needs a \"look\" object"), std::string::npos) << error;
}

} // namespace
} // namespace abalike
