// The colour-blind-safe look tells materials apart by pattern as well as colour: every material gets marks of its
// own on top of what the standard look draws.
#include "render/AbilityLook.hpp"
#include "render/BlockPainter.hpp"
#include "render/ConvexPolygon.hpp"
#include "render/Look.hpp"

#include <abalike/world/Catalog.hpp>
#include <gtest/gtest.h>

using namespace abalike;
using namespace abalike::app;

namespace
{
std::size_t verticesFor(const std::string& material, const Look& look)
{
    setActiveLook(look);
    Mesh mesh;
    BlockLook block;
    block.material = &Catalog::builtin().findMaterial(material)->look;
    block.pixelM = 0.02f;
    block.seed = 7;
    // A brick as the world builds it: 0.5 by 0.25 m, its corners chamfered by 1 cm.
    const float c = 0.01f;
    const std::vector<sf::Vector2f> brick{{-0.25f + c, -0.125f}, {0.25f - c, -0.125f}, {0.25f, -0.125f + c},
                                          {0.25f, 0.125f - c},   {0.25f - c, 0.125f},  {-0.25f + c, 0.125f},
                                          {-0.25f, 0.125f - c},  {-0.25f, -0.125f + c}};
    BlockPainter::paintPolygon(mesh, brick, block);
    setActiveLook(lookFor(Palette::Standard, false));
    return mesh.vertexCount();
}
} // namespace

TEST(BlockPatterns, EveryMaterialGetsItsOwnMarksInTheColourBlindSafeLook)
{
    for (const Material& each : Catalog::builtin().materials())
    {
        // A crate is told by its slats and its label in every look; the other surfaces add a pattern.
        if (each.look.surface == SurfaceKind::Crate)
            continue;
        const std::string& material = each.name;
        const std::size_t standard = verticesFor(material, lookFor(Palette::Standard, false));
        const std::size_t safe = verticesFor(material, lookFor(Palette::ColourBlindSafe, false));
        EXPECT_GE(safe, standard + 12) << material << ": at least a few pattern strokes or dots";
    }
}

TEST(BlockPatterns, AChamferedBrickStillGetsItsGrainSpecklesOrGlint)
{
    // Outline and fill of an octagon are 36 vertices; anything more is the material's detail. (Insetting moved each
    // vertex along its bisector before, which turned 1 cm chamfers inside out and silently dropped every detail.)
    for (const Material& material : Catalog::builtin().materials())
        EXPECT_GT(verticesFor(material.name, lookFor(Palette::Standard, false)), 36u) << material.name;
}

TEST(ConvexInset, ShortEdgesVanishInsteadOfTurningInsideOut)
{
    const float c = 0.01f;
    const std::vector<sf::Vector2f> brick{{-0.25f + c, -0.125f}, {0.25f - c, -0.125f}, {0.25f, -0.125f + c},
                                          {0.25f, 0.125f - c},   {0.25f - c, 0.125f},  {-0.25f + c, 0.125f},
                                          {-0.25f, 0.125f - c},  {-0.25f, -0.125f + c}};
    const std::vector<sf::Vector2f> inner = convex::inset(brick, 0.035f);
    ASSERT_GE(inner.size(), 4u);
    const sf::FloatRect box = convex::bounds(inner);
    EXPECT_NEAR(box.left, -0.215f, 1e-4f);
    EXPECT_NEAR(box.width, 0.43f, 1e-4f);
    EXPECT_NEAR(box.top, -0.09f, 1e-4f);
    EXPECT_NEAR(box.height, 0.18f, 1e-4f);
    EXPECT_GT(convex::signedArea(inner), 0.0f);
    sf::Vector2f a(-1.0f, 0.0f);
    sf::Vector2f b(1.0f, 0.0f);
    ASSERT_TRUE(convex::clipSegment(inner, a, b));
    EXPECT_NEAR(a.x, -0.215f, 1e-4f);
    EXPECT_NEAR(b.x, 0.215f, 1e-4f);
    EXPECT_TRUE(convex::inset(brick, 0.2f).empty()) << "inset past the middle: nothing left";
}

TEST(AbilityLooks, TheEggAndTheBlastHaveLooksOfTheirOwnAndTheRestTheDefault)
{
    EXPECT_TRUE(hasAbilityLook("egg"));
    EXPECT_TRUE(hasAbilityLook("explode"));
    EXPECT_FALSE(hasAbilityLook("split"));
    // The egg paints itself; a split bird is drawn as a bird of its type.
    Entity egg;
    egg.kind = EntityKind::Bird;
    egg.widthM = 0.4;
    Mesh mesh;
    EXPECT_TRUE(abilityLook("egg").paintBody(mesh, egg, 0.02f));
    EXPECT_GT(mesh.vertexCount(), 0u);
    Mesh none;
    EXPECT_FALSE(abilityLook("split").paintBody(none, egg, 0.02f));
    EXPECT_EQ(none.vertexCount(), 0u);
    // The black bird wears a fuse: a little more to draw than a bird without one.
    Mesh fuse;
    abilityLook("explode").decorateBird(fuse, 0.3f);
    EXPECT_GT(fuse.vertexCount(), 0u);
}
