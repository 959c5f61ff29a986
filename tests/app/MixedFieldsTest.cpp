#include "editor/MixedFields.hpp"

#include <abalike/level/LevelDef.hpp>
#include <gtest/gtest.h>

using namespace abalike;
using namespace abalike::app;

TEST(MixedFields, AMultiSelectionSharesAValueOnlyWhenEveryItemHasIt)
{
    // Three posts of one width and material, one of them taller: width and material are shared, height is mixed.
    std::vector<BlockDef> posts(3);
    for (BlockDef& post : posts)
    {
        post.widthM = 0.25;
        post.heightM = 2.0;
    }
    posts[2].heightM = 3.0;
    EXPECT_EQ(sharedValue(posts, [](const BlockDef& b) { return b.widthM; }), 0.25);
    EXPECT_FALSE(sharedValue(posts, [](const BlockDef& b) { return b.heightM; }).has_value());
    EXPECT_EQ(sharedValue(posts, [](const BlockDef& b) { return b.material; }), std::string("wood"));
    posts[1].material = "ice";
    EXPECT_FALSE(sharedValue(posts, [](const BlockDef& b) { return b.material; }).has_value());
    EXPECT_FALSE(sharedValue(std::vector<BlockDef>{}, [](const BlockDef& b) { return b.widthM; }).has_value());
}
