// bench feel's hit table tells the pieces a strike meets apart as the player does: roofs, plank ends, posts, hollow
// boxes and the rest.
#include "bench/HitTable.hpp"

#include <abalike/world/Catalog.hpp>
#include <abalike/world/GameWorld.hpp>
#include <box2d/box2d.h>
#include <gtest/gtest.h>

using namespace abalike;
using namespace abalike::app;

TEST(HitPiece, RoofsPlankEndsPostsHollowBoxesAndBlocks)
{
    LevelDef level;
    level.birds = {"red"};
    level.blocks.push_back({BlockShape::Box, "wood", 10.0, 2.0, 3.0, 0.25, 0.0});           // a plank, centre 2 m up
    level.blocks.push_back({BlockShape::Box, "wood", 14.0, 1.0, 0.25, 2.0, 0.0});           // a post
    level.blocks.push_back({BlockShape::Box, "wood", 18.0, 0.5, 1.0, 1.0, 0.0});            // a square block
    level.blocks.push_back({BlockShape::HollowBox, "wood", 22.0, 0.5, 1.0, 1.0, 0.0, 0.1}); // a hollow box
    level.pigs = {{"small", 30.0, 0.25}};
    GameWorld world(level, Catalog::builtin());
    world.step();
    const auto& e = world.entities();
    ASSERT_GE(e.size(), 5u);
    EXPECT_EQ(strikePiece(e[1], 2.125), "roof");      // on its upper face
    EXPECT_EQ(strikePiece(e[1], 2.0), "plank end");   // level with its middle: its end
    EXPECT_EQ(strikePiece(e[1], 1.875), "plank end"); // from below
    EXPECT_EQ(strikePiece(e[2], 1.5), "post");
    EXPECT_EQ(strikePiece(e[3], 0.5), "block");
    EXPECT_EQ(strikePiece(e[4], 0.5), "hollow box");
}
