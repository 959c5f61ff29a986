// PushApart's ways out of an overlap (check --fix and the Science Birds import): lifted off what is below, aside when
// that is the shorter way and the body still stands, lowered out of what is above when it cannot be lifted.
#include <abalike/level/LevelIO.hpp>
#include <abalike/level/PushApart.hpp>
#include <abalike/world/Catalog.hpp>

#include <gtest/gtest.h>

namespace abalike
{
namespace
{

BlockDef block(double x, double y, double w, double h)
{
    BlockDef def;
    def.material = "wood";
    def.x = x;
    def.y = y;
    def.widthM = w;
    def.heightM = h;
    return def;
}

PigDef smallPig(double x, double y)
{
    PigDef pig;
    pig.type = "small"; // radius 0.25 m
    pig.x = x;
    pig.y = y;
    return pig;
}

std::size_t overlapsLeft(const LevelDef& level)
{
    std::size_t count = 0;
    for (const LevelIssue& issue : checkLevelGeometry(level, Catalog::builtin()))
        count += issue.message.find("overlaps") != std::string::npos ? 1u : 0u;
    return count;
}

TEST(PushApart, APigMovedIntoAPostItCannotBeLiftedOverGoesAside)
{
    // A 1.5 m post on the ground and a pig on the ground 3 cm into it: lifting the pig over the post would take 1.5 m,
    // more than PushApart moves anything; aside is 3 cm.
    LevelDef level;
    level.blocks = {block(10.0, 0.75, 0.25, 1.5)};
    level.pigs = {smallPig(10.0 - 0.125 - 0.25 + 0.03, 0.25)};
    const std::vector<PushedBody> pushed = pushApartOverlaps(level, Catalog::builtin(), 0.005);
    ASSERT_EQ(pushed.size(), 1u);
    EXPECT_EQ(pushed[0].pointer, "/pigs/0");
    EXPECT_DOUBLE_EQ(level.pigs[0].y, 0.25);
    EXPECT_NEAR(level.pigs[0].x, 10.0 - 0.125 - 0.25, 0.0011);
    EXPECT_EQ(overlapsLeft(level), 0u);
}

TEST(PushApart, ABlockOnAStackAFewCentimetresIntoThePigBesideItGoesAsideNotUp)
{
    // A pig on the ground beside a stack: its side reaches 4.5 cm into the lower left corner of the upper block,
    // which rests on the block under it. Lifting the block clear of the pig is 10 cm and leaves it floating; aside is
    // 4.5 cm and it still stands on the block under it.
    LevelDef level;
    level.blocks = {block(10.6, 0.15, 0.6, 0.3), block(10.6, 0.5, 0.8, 0.4)};
    level.pigs = {smallPig(10.0, 0.25)};
    const std::vector<PushedBody> pushed = pushApartOverlaps(level, Catalog::builtin(), 0.005);
    ASSERT_EQ(pushed.size(), 1u);
    EXPECT_EQ(pushed[0].pointer, "/blocks/1");
    EXPECT_DOUBLE_EQ(level.blocks[1].y, 0.5);
    EXPECT_NEAR(level.blocks[1].x, 10.645, 0.0011);
    EXPECT_EQ(overlapsLeft(level), 0u);
}

TEST(PushApart, APlankRaisedIntoThePostsItCarriesGoesBackDownOntoItsOwnPosts)
{
    // Two storeys of posts and planks; the lower plank raised 29 cm into the upper posts. The upper posts' bottoms
    // are lower than the plank's now, so they are set first and the plank cannot be lifted over them (1.5 m): it is
    // lowered out of them, onto its own posts, and nothing else moves.
    LevelDef level;
    level.blocks = {block(9.0, 0.75, 0.25, 1.5), block(11.0, 0.75, 0.25, 1.5), block(10.0, 1.625 + 0.29, 2.6, 0.25),
                    block(9.0, 2.5, 0.25, 1.5), block(11.0, 2.5, 0.25, 1.5)};
    const std::vector<PushedBody> pushed = pushApartOverlaps(level, Catalog::builtin(), 0.005);
    ASSERT_EQ(pushed.size(), 1u);
    EXPECT_EQ(pushed[0].pointer, "/blocks/2");
    EXPECT_NEAR(pushed[0].dyM, -0.29, 1e-9);
    EXPECT_NEAR(level.blocks[2].y, 1.625, 1e-9);
    EXPECT_DOUBLE_EQ(level.blocks[3].y, 2.5);
    EXPECT_DOUBLE_EQ(level.blocks[4].y, 2.5);
    EXPECT_EQ(overlapsLeft(level), 0u);
}

TEST(PushApart, APostSunkDeepIntoThePostBelowGoesUpNotAside)
{
    // A 2 m post sunk 1.3 m into the 1.5 m post under it: aside (25 cm) is shorter than up (1.3 m), but aside it
    // would stand on nothing, 20 cm above the ground: it goes up.
    LevelDef level;
    level.blocks = {block(10.0, 0.75, 0.25, 1.5), block(10.0, 1.5 - 1.3 + 1.0, 0.25, 2.0)};
    const std::vector<PushedBody> pushed = pushApartOverlaps(level, Catalog::builtin(), 0.005);
    ASSERT_EQ(pushed.size(), 1u);
    EXPECT_EQ(pushed[0].pointer, "/blocks/1");
    EXPECT_DOUBLE_EQ(level.blocks[1].x, 10.0);
    EXPECT_NEAR(level.blocks[1].y, 2.5, 1e-9);
}

} // namespace
} // namespace abalike
