// What the editor says when a block or pig it placed, dropped, pasted or moved does not land (issue 56, item 4).
#include <abalike/edit/Landing.hpp>
#include <abalike/edit/SceneEditor.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/world/Catalog.hpp>

#include <gtest/gtest.h>

namespace abalike
{
namespace
{

TEST(Landing, ABodyPlacedBeyondTheSnapSaysWhereItFloatsAndThatItFalls)
{
    // A stone slab on the ground, a wood post 25 cm above it (beyond the editor's 10 cm reach), a pig 25 cm above the
    // ground beside it, and a pig resting on the slab.
    SceneEditor editor(emptyScene());
    editor.snapSettings().grid = false;
    editor.snapSettings().surfaces = false; // placed exactly where asked, as after a drag with snapping off
    const ObjectRef slab = editor.place(BlockDef{BlockShape::Box, "stone", 10.0, 0.25, 3.0, 0.5, 0.0, 0.1});
    const ObjectRef post = editor.place(BlockDef{BlockShape::Box, "wood", 10.0, 0.5 + 0.25 + 1.0, 0.25, 2.0, 0.0, 0.1});
    const ObjectRef high = editor.place(PigDef{"small", 14.0, 0.25 + 0.25});
    const ObjectRef resting = editor.place(PigDef{"small", 11.0, 0.5 + 0.25});
    const Catalog& catalog = Catalog::builtin();

    EXPECT_EQ(whyNotLanded(editor.level(), catalog, {slab, resting}, 0.1), std::nullopt);
    EXPECT_EQ(whyNotLanded(editor.level(), catalog, {post}, 0.1),
              "block 1 floats 25.0 cm above block 0 (stone), more than the 10.0 cm the editor pulls a body down: it "
              "falls when the level starts; drag it down onto block 0 (stone)");
    EXPECT_EQ(whyNotLanded(editor.level(), catalog, {high, post, slab}, 0.1),
              "pig 0 floats 25.0 cm above the ground, more than the 10.0 cm the editor pulls a body down: it falls "
              "when the level starts; drag it down onto the ground (and 1 more placed the same way)");
    const ObjectRef sky = editor.place(PigDef{"medium", 20.0, 7.35});
    EXPECT_EQ(whyNotLanded(editor.level(), catalog, {sky}, 0.1),
              "pig 2 is 7.00 m above the ground with nothing under it: it falls when the level starts");
    // Terrain and the slingshot are not bodies that fall.
    EXPECT_EQ(whyNotLanded(editor.level(), catalog, {ObjectRef{ObjectKind::Slingshot, 0}}, 0.1), std::nullopt);
}

TEST(Landing, WithSnappingOnAPlacedBodyLandsAndNothingIsSaid)
{
    SceneEditor editor(emptyScene());
    editor.snapSettings().surfaceReachM = 0.1;
    const ObjectRef slab = editor.place(BlockDef{BlockShape::Box, "stone", 10.0, 0.25, 3.0, 0.5, 0.0, 0.1});
    // 6 cm above the slab: pulled down onto it.
    const ObjectRef pig = editor.place(PigDef{"small", 10.5, 0.5 + 0.25 + 0.06});
    EXPECT_EQ(whyNotLanded(editor.level(), Catalog::builtin(), {slab, pig}, 0.1), std::nullopt);
}

} // namespace
} // namespace abalike
